// terrain-sketch pstrokes: the P-stroke sketch.
#include <ostream>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/applications/pstrokes.h"
#include "io/write/vector_writer.h"

namespace tsk::cli {

int pstrokes(const Args& args, std::ostream& out, std::ostream& err, const ProgressFn& progress) {
  const Options o = parse("pstrokes", args);
  o.pstrokes.validate();
  io::check_vector_output(o.output, o.format);
  const io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  const SilhouetteResult result = sketch_whole(o, held, progress, err);
  stop_if_interrupted();
  const auto strokes =
      pstroke_sketch(dem.oriented, result.flags, dem.frame, o.params.view, dem.geotransform,
                     o.params.geometry, o.pstrokes, dem.lowest_height, o.params.threads);
  io::write_pstrokes(o.output, o.format, strokes, dem.srs_wkt);
  out << o.output << ": " << strokes.size() << " P-strokes\n";
  return 0;
}

}  // namespace tsk::cli
