// terrain-sketch profiles: the profile plot as lines.
#include <ostream>
#include <string>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/method/run_note.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {

std::string profiles(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& /* their steps report no progress */) {
  const Options o = parse("profiles", args);
  io::check_vector_output(o.output, o.format);
  const io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  const auto lines = plot_profiles(held.held(), o.params.view, static_cast<std::size_t>(o.every),
                                   o.params.threads);
  stop_if_interrupted();
  io::write_profile_lines(o.output, o.format, lines, dem.srs_wkt,
                          product_note(run_facts(o), "Profile lines", false));
  out << o.output << ": " << lines.size() << " visible cross-section pieces\n";
  return {};
}

}  // namespace tsk::cli
