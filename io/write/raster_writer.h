// Grids on the DEM's grid to rasters (GeoTIFF, or the GDAL format of the file's extension), whole
// or not at all. A GeoTIFF keeps `description` (what made it: run_note.h) as its image
// description (TIFFTAG_IMAGEDESCRIPTION), which gdalinfo and QGIS's layer properties show.
#pragma once

#include <gdal_priv.h>

#include <cstdint>
#include <string>
#include <vector>

#include "core/applications/diagnostics.h"
#include "core/base/geotransform.h"
#include "core/method/strokes.h"

namespace tsk::io {

// The GDAL driver that creates rasters with `path`'s extension (GTiff for .tif, .tiff or none);
// throws Error when no driver does.
GDALDriver* raster_driver_for(const std::string& path);

// Float32, nodata NaN, one band per grid (all of one size).
void write_float_raster(const std::string& path, const std::vector<HeightGrid>& bands,
                        const GeoTransform& gt, const std::string& srs_wkt,
                        const std::string& description = {});

// Byte classes with a colour table and class names (0 is nodata), for QGIS and other viewers.
void write_classification(const std::string& path, const Grid<std::uint8_t>& classes,
                          const GeoTransform& gt, const std::string& srs_wkt,
                          const std::string& description = {});

// A panorama's visibility on the DEM's grid: 1 visible, 0 hidden, 255 out of range (nodata), with
// a colour table and class names.
void write_visibility(const std::string& path, const Grid<std::uint8_t>& visibility,
                      const GeoTransform& gt, const std::string& srs_wkt,
                      const std::string& description = {});

}  // namespace tsk::io
