// A raster held in the caller's memory (a numpy array from the Python package) as a GDAL dataset
// of its own, without a copy: so that it is described, checked and read as a DEM file is
// (dem_reader.h), with the same messages.
#pragma once

#include <gdal.h>

#include <cstddef>
#include <optional>
#include <string>

#include "core/base/geotransform.h"
#include "io/read/gdal_util.h"

namespace tsk::io {

// The caller's values: `rows` x `cols` of `type`, the first at `data`, the next along a row
// `column_step` bytes on and the next down a column `row_step` bytes on (both at least a value's
// size: a row-major array, or a view of one laid out column by column).
struct MemoryBand {
  const void* data = nullptr;
  GDALDataType type = GDT_Float32;
  std::size_t rows = 0, cols = 0;
  std::size_t column_step = 0, row_step = 0;
};

struct MemoryRasterInfo {
  std::optional<GeoTransform> geotransform;  // none: a raster without georeferencing
  std::string crs;                           // WKT, "EPSG:N", PROJ: anything GDAL reads; or ""
  std::optional<double> nodata;
};

// A dataset of one band over the caller's values, which must outlive it and stay unchanged.
// Throws Error on a size GDAL cannot hold (over 2^31 - 1 rows or columns), steps that do not
// hold a value, or a CRS GDAL does not know.
DatasetPtr wrap_memory_raster(const MemoryBand& band, const MemoryRasterInfo& info);

}  // namespace tsk::io
