// terrain-sketch filter-plot: the slope filter diagram as an HTML page.
#include <filesystem>
#include <ostream>
#include <string>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "io/pages/filter_diagram_page.h"
#include "io/write/output_files.h"

namespace tsk::cli {

std::string filter_plot(const Args& args, std::ostream& out, std::ostream& err,
                        const ProgressFn& progress) {
  const Options o = parse("filter-plot", args);
  require_html(o.output);
  const io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  const SilhouetteResult result = sketch_whole(o, held, progress, err);
  stop_if_interrupted();
  io::write_text_file(
      o.output,
      filter_diagram_html(slope_scatter_of(dem.oriented, dem.frame, result), result.filter.cutoffs,
                          "Slope filter: " + std::filesystem::path(o.input).filename().string()));
  out << o.output << ": c-set " << result.stats.pct(result.stats.candidate) << " %, f-set "
      << result.stats.pct(result.stats.filtered) << " %\n";
  return {};
}

}  // namespace tsk::cli
