// Writes grids on the DEM's grid as one-band rasters with the DEM's extent and CRS.
#pragma once

#include <QString>
#include <cstdint>

#include "grid.h"

class QgsRasterBlock;

namespace tsk::plugin {

class RasterGrid;

// Byte classes, nodata 0.
void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem);
// Float32, nodata NaN.
void writeFloatRaster(const QString& path, const HeightGrid& grid, const RasterGrid& dem);

}  // namespace tsk::plugin
