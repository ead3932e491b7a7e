// terrain-sketch drape: a raster on the DEM's grid into plan-oblique space.
#include <ostream>
#include <utility>
#include <vector>

#include "command_support.h"
#include "commands.h"
#include "dem_reader.h"
#include "drape.h"
#include "interrupt.h"
#include "raster_writer.h"
#include "visibility.h"

namespace tsk::cli {
namespace {

PlanObliqueDrape lay_out(const io::Dem& dem, const SilhouetteParams& params) {
  CellFlags flags;
  classify_visibility(dem.oriented, dem.frame.d, params.view, flags, params.threads);
  return PlanObliqueDrape(dem.oriented, flags, dem.frame, params.view, dem.lowest_height);
}

}  // namespace

int drape(const Args& args, std::ostream& out, std::ostream& err,
          const ProgressFn& /* their steps report no progress */) {
  const Options o = parse(args);
  require_geotiff(o.output);
  if (o.source.empty()) throw Error("drape needs --source RASTER, the raster to drape");
  io::Dem dem = load_dem(o, err);
  const PlanObliqueDrape drape = lay_out(dem, o.params);
  dem.oriented = HeightGrid();  // the DEM goes before the bands are read and draped
  std::vector<HeightGrid> source = io::read_bands(o.source);
  std::vector<HeightGrid> bands;
  for (HeightGrid& band : source) bands.push_back(drape.drape(std::move(band)));
  stop_if_interrupted();
  io::write_float_raster(o.output, bands, drape.geotransform(dem.geotransform), dem.srs_wkt);
  out << o.output << ": " << bands.size() << " band(s) draped, " << drape.cols() << " x "
      << drape.rows() << " cells\n";
  return 0;
}

}  // namespace tsk::cli
