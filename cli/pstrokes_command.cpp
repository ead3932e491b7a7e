// terrain-sketch pstrokes: the P-stroke sketch.
#include <ostream>
#include <string>
#include <vector>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/method/run_note.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {

std::string pstrokes(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress) {
  const Options o = parse("pstrokes", args);
  io::check_vector_output(o.output, o.format);
  const io::HeldDemFile held = load_dem(o, err);
  const PStrokeRun run = sketch_pstrokes(held.held(), o.params, o.pstrokes, progress);
  print_filter(run.filter, err);
  const std::vector<PStroke>& strokes = run.strokes;
  stop_if_interrupted();
  io::write_pstrokes(o.output, o.format, strokes, held.dem.srs_wkt,
                     product_note(run_facts(o, run.filter), "P-strokes", true));
  out << o.output << ": " << strokes.size() << " P-strokes\n";
  return {};
}

}  // namespace tsk::cli
