// Helpers for tests that go through GDAL: scratch folders and small rasters made on the spot.
#pragma once

#include <gdal_priv.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "cli_app.h"

namespace tsk::test {

namespace fs = std::filesystem;

// A fresh folder removed at the end of the test.
struct ScratchDir {
  fs::path path;
  explicit ScratchDir(const std::string& name)
      : path(fs::temp_directory_path() / ("tsk-test-" + std::to_string(getpid()) + "-" + name)) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchDir() { fs::remove_all(path); }
  std::string operator/(const std::string& file) const { return (path / file).string(); }
  std::size_t file_count() const {
    return static_cast<std::size_t>(
        std::distance(fs::directory_iterator(path), fs::directory_iterator{}));
  }
};

struct CliRun {
  int code;
  std::string out, err;
};

inline CliRun run_cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = cli::run(args, out, err);
  return {code, out.str(), err.str()};
}

// Writes a GeoTIFF of `bands` bands filled by f(band, row, col), with an optional geotransform
// and EPSG code (0: none).
template <typename F>
void write_tiff(const std::string& path, int rows, int cols, int bands, F f,
                const double* geotransform, int epsg) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDataset* ds = drv->Create(path.c_str(), cols, rows, bands, GDT_Float32, nullptr);
  for (int b = 1; b <= bands; ++b) {
    std::vector<float> values(static_cast<std::size_t>(rows) * cols);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) values[static_cast<std::size_t>(r) * cols + c] = f(b, r, c);
    if (ds->GetRasterBand(b)->RasterIO(GF_Write, 0, 0, cols, rows, values.data(), cols, rows,
                                       GDT_Float32, 0, 0) != CE_None) {
      throw std::runtime_error("test raster write failed");
    }
  }
  if (geotransform) ds->SetGeoTransform(const_cast<double*>(geotransform));
  if (epsg) {
    OGRSpatialReference srs;
    srs.importFromEPSG(epsg);
    ds->SetSpatialRef(&srs);
  }
  GDALClose(ds);
}

}  // namespace tsk::test
