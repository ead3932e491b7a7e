// terrain-sketch row-slope: |slope across the line of sight| as a GeoTIFF.
#include <ostream>
#include <string>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/applications/diagnostics.h"
#include "core/method/run_note.h"
#include "io/write/raster_writer.h"

namespace tsk::cli {

std::string row_slope(const Args& args, std::ostream& out, std::ostream& err,
                      const ProgressFn& /* their steps report no progress */) {
  const Options o = parse("row-slope", args);
  require_geotiff(o.output);
  const io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  const HeightGrid slope = row_slope_map(dem.oriented, dem.frame);
  stop_if_interrupted();
  io::write_float_raster(o.output, {slope}, dem.geotransform, dem.srs_wkt,
                         product_note(run_facts(o), "Row slope", false));
  out << o.output << ": row slope in percent across azimuth " << dem.frame.azimuth_deg << "\n";
  return {};
}

}  // namespace tsk::cli
