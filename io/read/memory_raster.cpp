#include "io/read/memory_raster.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <climits>
#include <cstdio>

#include "core/base/errors.h"

namespace tsk::io {
namespace {

// The MEM driver takes the address and steps of a band's values as creation options.
std::string option(const char* name, const std::string& value) {
  return std::string(name) + "=" + value;
}

std::string address_text(const void* data) {
  char text[32];
  std::snprintf(text, sizeof text, "%p", data);
  return text;
}

void check_shape(const MemoryBand& band) {
  constexpr auto most = static_cast<std::size_t>(INT_MAX);
  if (band.rows == 0 || band.cols == 0 || band.rows > most || band.cols > most) {
    throw Error("the array has " + std::to_string(band.rows) + " x " + std::to_string(band.cols) +
                " cells; a DEM needs 1 to " + std::to_string(most) + " of each");
  }
  const auto size = static_cast<std::size_t>(GDALGetDataTypeSizeBytes(band.type));
  if (!band.data || size == 0 || band.column_step < size || band.row_step < size)
    throw Error("the array's values overlap: copy it first (numpy.ascontiguousarray)");
}

}  // namespace

DatasetPtr wrap_memory_raster(const MemoryBand& band, const MemoryRasterInfo& info) {
  check_shape(band);
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("MEM");
  if (!driver) throw Error("GDAL has no MEM driver, which holds an array as a raster");
  GdalErrorCapture capture;
  DatasetPtr dataset(driver->Create("", static_cast<int>(band.cols), static_cast<int>(band.rows), 0,
                                    GDT_Byte, nullptr));
  if (!dataset) throw Error("holding the array as a raster failed: " + capture.message());
  const std::string options[] = {option("DATAPOINTER", address_text(band.data)),
                                 option("PIXELOFFSET", std::to_string(band.column_step)),
                                 option("LINEOFFSET", std::to_string(band.row_step))};
  const char* const list[] = {options[0].c_str(), options[1].c_str(), options[2].c_str(), nullptr};
  if (dataset->AddBand(band.type, const_cast<char**>(list)) != CE_None)
    throw Error("holding the array as a raster failed: " + capture.message());
  if (info.geotransform) {
    GeoTransform gt = *info.geotransform;
    dataset->SetGeoTransform(gt.a.data());
  }
  if (!info.crs.empty()) {
    OGRSpatialReference srs;
    if (srs.SetFromUserInput(info.crs.c_str()) != OGRERR_NONE) {
      // Text that is no form of CRS at all fails without a word from GDAL.
      const std::string why = capture.first_failure().empty()
                                  ? "give it as WKT, \"EPSG:N\" or a PROJ string"
                                  : capture.first_failure();
      throw Error("the CRS '" + info.crs + "' is none GDAL knows: " + why);
    }
    dataset->SetSpatialRef(&srs);
  }
  if (info.nodata) dataset->GetRasterBand(1)->SetNoDataValue(*info.nodata);
  return dataset;
}

}  // namespace tsk::io
