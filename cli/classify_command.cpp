// terrain-sketch classify: the stage of every DEM cell as a GeoTIFF.
#include <ostream>
#include <string>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/applications/diagnostics.h"
#include "core/method/run_note.h"
#include "io/write/raster_writer.h"

namespace tsk::cli {

std::string classify(const Args& args, std::ostream& out, std::ostream& err,
                     const ProgressFn& progress) {
  const Options o = parse("classify", args);
  require_geotiff(o.output);
  const io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  const SilhouetteResult result = sketch_whole(o, held, progress, err);
  stop_if_interrupted();
  io::write_classification(o.output, classification_map(result.flags, dem.frame), dem.geotransform,
                           dem.srs_wkt,
                           product_note(run_facts(o, result.filter), "Silhouette stages", true));
  const std::string statistics = report_statistics(o, result.stats, result.filter);
  const StageStats& s = result.stats;
  out << o.output << ": hidden " << s.pct(s.hidden) << " %, occluding " << s.pct(s.occluding)
      << " %, c-set " << s.pct(s.candidate) << " %, f-set " << s.pct(s.filtered) << " %, t-set "
      << s.pct(s.thinned) << " %\n";
  return statistics;
}

}  // namespace tsk::cli
