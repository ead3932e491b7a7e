// Writes grids as rasters on the DEM's grid or another (the drape's) in the DEM's CRS, through
// io/'s raster writer: whole or not at all, in the GDAL format of the file's extension. A GeoTIFF
// keeps `note` (what made it: run_notes.h) as its image description.
#pragma once

#include <qgscoordinatereferencesystem.h>

#include <QString>
#include <cstdint>
#include <vector>

#include "core/base/geotransform.h"
#include "core/base/grid.h"

namespace tsk::plugin {

class RasterGrid;

// Byte classes on the DEM's grid, nodata 0.
void writeByteRaster(const QString& path, const Grid<std::uint8_t>& grid, const RasterGrid& dem,
                     const QString& note);
// A panorama's visibility on the DEM's grid: 1 visible, 0 hidden, 255 out of range (nodata).
void writeVisibilityRaster(const QString& path, const Grid<std::uint8_t>& grid,
                           const RasterGrid& dem, const QString& note);
// Float32 bands (all of one size), nodata NaN.
void writeFloatRaster(const QString& path, const std::vector<HeightGrid>& bands,
                      const GeoTransform& geotransform, const QgsCoordinateReferenceSystem& crs,
                      const QString& note);

}  // namespace tsk::plugin
