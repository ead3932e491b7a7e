// Helpers for tests that go through GDAL: scratch folders and small rasters made on the spot.
#pragma once

#include <gdal_priv.h>
#include <gdal_utils.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace tsk::test {

namespace fs = std::filesystem;

// The bytes of the file at `path` ("" when it cannot be read).
inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

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

// Writes a GeoTIFF of `bands` bands filled by f(band, row, col), with an optional geotransform,
// EPSG code (0: none) and nodata value (NaN: none).
template <typename F>
void write_tiff(const std::string& path, int rows, int cols, int bands, F f,
                const double* geotransform, int epsg, double nodata = std::nan("")) {
  GDALAllRegister();
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDataset* ds = drv->Create(path.c_str(), cols, rows, bands, GDT_Float32, nullptr);
  for (int b = 1; b <= bands; ++b) {
    if (!std::isnan(nodata)) ds->GetRasterBand(b)->SetNoDataValue(nodata);
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

// Marks the first three bands of the raster at `path` as an image's red, green and blue.
inline void mark_rgb(const std::string& path) {
  GDALAllRegister();
  GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_Update));
  if (!ds) throw std::runtime_error("cannot open " + path);
  for (const auto& [band, colour] :
       {std::pair{1, GCI_RedBand}, std::pair{2, GCI_GreenBand}, std::pair{3, GCI_BlueBand}})
    ds->GetRasterBand(band)->SetColorInterpretation(colour);
  GDALClose(ds);
}

// Copies the raster `from` into a new GeoPackage `to`, as a DEM kept in one.
inline void copy_raster_to_gpkg(const std::string& from, const std::string& to) {
  GDALAllRegister();
  GDALDatasetH source = GDALOpen(from.c_str(), GA_ReadOnly);
  GDALDatasetH copy = source ? GDALCreateCopy(GDALGetDriverByName("GPKG"), to.c_str(), source,
                                              false, nullptr, nullptr, nullptr)
                             : nullptr;
  if (copy) GDALClose(copy);
  if (source) GDALClose(source);
  if (!copy) throw std::runtime_error("test GeoPackage raster copy failed");
}

// North-up, 10 m cells, in UTM.
inline const double kNorthUp[6] = {500000, 10, 0, 4000000, 0, -10};

// A round hill 300 m high on a 40 x 40 grid, for write_tiff.
inline float hill(int, int r, int c) {
  return static_cast<float>(300 * std::exp(-((r - 20) * (r - 20) + (c - 20) * (c - 20)) / 60.0));
}

// A 40 x 80 VRT at `vrt` whose top half is the 40 x 40 GeoTIFF `top` beside it and whose bottom
// half's file, gone.tif, does not exist: it opens, and reading it fails halfway down.
inline void write_half_missing_vrt(const std::string& vrt, const std::string& top) {
  std::ofstream(vrt) << R"(<VRTDataset rasterXSize="40" rasterYSize="80">
  <SRS>EPSG:32616</SRS>
  <GeoTransform>500000, 10, 0, 4000000, 0, -10</GeoTransform>
  <VRTRasterBand dataType="Float32" band="1">
    <SimpleSource>
      <SourceFilename relativeToVRT="1">)"
                     << top << R"(</SourceFilename><SourceBand>1</SourceBand>
      <SrcRect xOff="0" yOff="0" xSize="40" ySize="40"/>
      <DstRect xOff="0" yOff="0" xSize="40" ySize="40"/>
    </SimpleSource>
    <SimpleSource>
      <SourceFilename relativeToVRT="1">gone.tif</SourceFilename><SourceBand>1</SourceBand>
      <SrcRect xOff="0" yOff="0" xSize="40" ySize="40"/>
      <DstRect xOff="0" yOff="40" xSize="40" ySize="40"/>
    </SimpleSource>
  </VRTRasterBand>
</VRTDataset>)";
}

// A VRT of 100000 x 100000 cells with no source (every cell nodata): it opens at once, and
// holding it whole would take 50 GB.
inline void write_huge_vrt(const std::string& vrt) {
  std::ofstream(vrt) << R"(<VRTDataset rasterXSize="100000" rasterYSize="100000">
  <SRS>EPSG:32616</SRS>
  <GeoTransform>500000, 10, 0, 4000000, 0, -10</GeoTransform>
  <VRTRasterBand dataType="Float32" band="1"><NoDataValue>-9999</NoDataValue></VRTRasterBand>
</VRTDataset>)";
}

// Writes a VRT at `path` reading the raster `source` (GDAL then lists the VRT and `source` as its
// files, not the sources of `source`).
inline void build_vrt(const std::string& path, const std::string& source) {
  GDALAllRegister();
  const char* sources[] = {source.c_str()};
  int failed = 0;
  GDALDatasetH built = GDALBuildVRT(path.c_str(), 1, nullptr, sources, nullptr, &failed);
  REQUIRE(built != nullptr);
  GDALClose(built);
}

}  // namespace tsk::test
