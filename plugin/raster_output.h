// Writes grids as rasters with a given extent and CRS (the DEM's, or the drape's).
#pragma once

#include <qgscoordinatereferencesystem.h>
#include <qgsrectangle.h>

#include <QString>
#include <cstdint>
#include <vector>

#include "grid.h"

namespace tsk::plugin {

class RasterGrid;

// Byte classes on the DEM's grid, nodata 0.
void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem);
// Float32 bands (all of one size), nodata NaN.
void writeFloatRaster(const QString& path, const std::vector<HeightGrid>& bands,
                      const QgsRectangle& extent, const QgsCoordinateReferenceSystem& crs);

}  // namespace tsk::plugin
