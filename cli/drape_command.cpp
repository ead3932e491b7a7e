// terrain-sketch drape: a raster on the DEM's grid into plan-oblique space.
#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/command_support.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "core/applications/drape.h"
#include "core/method/run_note.h"
#include "io/read/dem_reader.h"
#include "io/write/raster_writer.h"

namespace tsk::cli {
std::string drape(const Args& args, std::ostream& out, std::ostream& err,
                  const ProgressFn& /* their steps report no progress */) {
  const Options o = parse("drape", args);
  require_geotiff(o.output);
  if (o.source.empty()) throw UsageError("drape needs --source RASTER, the raster to drape");
  io::HeldDemFile held = load_dem(o, err);
  const io::Dem& dem = held.dem;
  io::require_on_dem_grid(o.source, dem);  // before the work
  const PlanObliqueDrape drape = lay_out_drape(held.held(), o.params.view, o.params.threads);
  held.dem.oriented = HeightGrid();  // the DEM goes before the bands are read and draped
  std::vector<HeightGrid> source = io::read_bands(o.source);
  std::vector<HeightGrid> bands;
  for (HeightGrid& band : source) bands.push_back(drape.drape(std::move(band)));
  stop_if_interrupted();
  io::write_float_raster(
      o.output, bands, drape.geotransform(dem.geotransform), dem.srs_wkt,
      product_note(run_facts(o),
                   "A drape of " + std::filesystem::path(o.source).filename().string(), false));
  out << o.output << ": " << bands.size() << " band(s) draped, " << drape.cols() << " x "
      << drape.rows() << " cells\n";
  return {};
}

}  // namespace tsk::cli
