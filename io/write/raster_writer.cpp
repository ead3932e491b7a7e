#include "io/write/raster_writer.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal_priv.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "io/read/gdal_util.h"
#include "io/write/output_files.h"

namespace tsk::io {
namespace {

// True when `count` values of `type` read back as they were written (NaN as NaN).
bool same_values(GDALDataType type, const void* written, const void* read, std::size_t count) {
  if (type == GDT_Byte)
    return std::equal(static_cast<const GByte*>(written),
                      static_cast<const GByte*>(written) + count, static_cast<const GByte*>(read));
  const auto* a = static_cast<const float*>(written);
  const auto* b = static_cast<const float*>(read);
  for (std::size_t k = 0; k < count; ++k)
    if (a[k] != b[k] && !(std::isnan(a[k]) && std::isnan(b[k]))) return false;
  return true;
}

// Reads every band of the raster at `staged` back, a block of rows at a time, and compares it
// with the `pixels` written (Byte or Float32). GDAL 3.10's GeoTIFF driver leaves a full disk
// unsaid (libtiff prints it, no error is raised and the close succeeds), so a raster is whole only
// when it reads back; and a format may change the values (a GeoPackage's PNG tiles renumber a
// colour table), which no output may.
void check_reads_back(const std::string& path, const std::filesystem::path& staged,
                      GDALDataType type, const std::vector<const void*>& pixels) {
  GdalErrorCapture capture;
  const NoAuxFiles no_aux;
  DatasetPtr ds(static_cast<GDALDataset*>(
      GDALOpenEx(staged.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr)));
  const auto fail = [&] {
    throw Error("writing '" + path + "' failed: it does not read back (" +
                (capture.first_failure().empty() ? std::string("is the disk full?")
                                                 : capture.first_failure()) +
                ")");
  };
  if (!ds) fail();
  if (ds->GetRasterCount() != static_cast<int>(pixels.size())) {
    throw Error("writing '" + path + "' failed: the " + ds->GetDriver()->GetDescription() +
                " format gave back " + std::to_string(ds->GetRasterCount()) + " bands for the " +
                std::to_string(pixels.size()) + " written; use .tif");
  }
  const int cols = ds->GetRasterXSize(), rows = ds->GetRasterYSize();
  const int block_rows = std::max(1, std::min(rows, (1 << 22) / std::max(1, cols)));
  const auto value_bytes = static_cast<std::size_t>(GDALGetDataTypeSizeBytes(type));
  std::vector<GByte> buffer(static_cast<std::size_t>(cols) * block_rows * value_bytes);
  for (int b = 1; b <= ds->GetRasterCount(); ++b) {
    for (int top = 0; top < rows; top += block_rows) {
      const int count = std::min(block_rows, rows - top);
      if (ds->GetRasterBand(b)->RasterIO(GF_Read, 0, top, cols, count, buffer.data(), cols, count,
                                         type, 0, 0) != CE_None) {
        fail();
      }
      const std::size_t first = static_cast<std::size_t>(top) * cols;
      const auto* written = static_cast<const GByte*>(pixels[b - 1]) + first * value_bytes;
      if (!same_values(type, written, buffer.data(), static_cast<std::size_t>(count) * cols)) {
        throw Error("writing '" + path + "' failed: the " + ds->GetDriver()->GetDescription() +
                    " format changed the values written; use .tif");
      }
    }
  }
  if (!capture.first_failure().empty()) fail();
}

// GeoTIFF outputs: tiled and compressed at DEFLATE's level 3, which on the 4000² benchmark's
// classification took a quarter of level 6's (GDAL's default) time for 7 % more bytes, the blocks
// compressed on every core unless GDAL_NUM_THREADS says otherwise (classify 2.05 s -> 1.01 s).
CPLStringList tiff_options() {
  CPLStringList options;
  options.SetNameValue("COMPRESS", "DEFLATE");
  options.SetNameValue("ZLEVEL", "3");
  options.SetNameValue("TILED", "YES");
  options.SetNameValue("BIGTIFF", "IF_SAFER");
  if (!CPLGetConfigOption("GDAL_NUM_THREADS", nullptr))
    options.SetNameValue("NUM_THREADS", "ALL_CPUS");
  return options;
}

// Where a raster goes on the ground, and what it records of the run that made it.
struct RasterPlace {
  const GeoTransform& gt;
  const std::string& srs_wkt;
  const std::string& description;
};

// Creates a raster of pixels.size() bands at `staged` in the format of `path`'s extension, lets
// `fill` set up each band, writes the pixels. Every failure GDAL reports fails the write: a full
// disk shows only as an error when GDAL writes its cached blocks while it closes the file.
template <typename Fill>
void write_bands(const std::string& path, const std::filesystem::path& staged, std::size_t rows,
                 std::size_t cols, GDALDataType type, const std::vector<const void*>& pixels,
                 const RasterPlace& place, Fill fill) {
  GdalErrorCapture capture;
  GDALDriver* driver = raster_driver_for(path);
  const bool tiff = std::string(driver->GetDescription()) == "GTiff";
  DatasetPtr ds(driver->Create(staged.c_str(), static_cast<int>(cols), static_cast<int>(rows),
                               static_cast<int>(pixels.size()), type,
                               tiff ? tiff_options().List() : nullptr));
  if (!ds) throw Error("cannot create '" + path + "': " + capture.message());
  double transform[6];
  std::copy(place.gt.a.begin(), place.gt.a.end(), transform);
  ds->SetGeoTransform(transform);
  if (!place.srs_wkt.empty()) ds->SetProjection(place.srs_wkt.c_str());
  // Other formats would keep it in a side file (.aux.xml) that the staging leaves behind.
  if (tiff && !place.description.empty())
    ds->SetMetadataItem("TIFFTAG_IMAGEDESCRIPTION", place.description.c_str());
  for (std::size_t b = 0; b < pixels.size(); ++b) {
    GDALRasterBand* band = ds->GetRasterBand(static_cast<int>(b) + 1);
    fill(*band);
    if (band->RasterIO(GF_Write, 0, 0, static_cast<int>(cols), static_cast<int>(rows),
                       const_cast<void*>(pixels[b]), static_cast<int>(cols), static_cast<int>(rows),
                       type, 0, 0) != CE_None) {
      throw Error("writing '" + path + "' failed: " + capture.message());
    }
  }
  const bool closed = close_dataset(ds);
  if (!capture.first_failure().empty()) {
    throw Error("writing '" + path + "' failed: " + capture.first_failure());
  }
  if (!closed) throw Error("writing '" + path + "' failed as it was closed (is the disk full?)");
  check_reads_back(path, staged, type, pixels);
}

}  // namespace

GDALDriver* raster_driver_for(const std::string& path) {
  GDALAllRegister();
  std::string ext = lowercase_extension(path);
  if (!ext.empty()) ext.erase(0, 1);
  if (ext.empty() || ext == "tiff") ext = "tif";
  GDALDriverManager& drivers = *GetGDALDriverManager();
  for (int k = 0; k < drivers.GetDriverCount(); ++k) {
    GDALDriver* driver = drivers.GetDriver(k);
    const char* raster = driver->GetMetadataItem(GDAL_DCAP_RASTER);
    const char* create = driver->GetMetadataItem(GDAL_DCAP_CREATE);
    const char* extensions = driver->GetMetadataItem(GDAL_DMD_EXTENSIONS);
    if (!raster || !create || !extensions) continue;
    const CPLStringList list(CSLTokenizeString(extensions));
    for (int e = 0; e < list.size(); ++e)
      if (EQUAL(list[e], ext.c_str())) return driver;
  }
  throw Error("no raster format that GDAL can create has the extension of '" + path +
              "'; use .tif");
}

void write_float_raster(const std::string& path, const std::vector<HeightGrid>& bands,
                        const GeoTransform& gt, const std::string& srs_wkt,
                        const std::string& description) {
  if (bands.empty()) throw Error("nothing to write to '" + path + "'");
  std::vector<const void*> pixels;
  for (const HeightGrid& b : bands) pixels.push_back(b.data());
  write_atomically(path, [&](const std::filesystem::path& staged) {
    write_bands(path, staged, bands[0].rows(), bands[0].cols(), GDT_Float32, pixels,
                {gt, srs_wkt, description}, [](GDALRasterBand& band) {
                  band.SetNoDataValue(std::numeric_limits<double>::quiet_NaN());
                });
  });
}

void write_classification(const std::string& path, const Grid<std::uint8_t>& classes,
                          const GeoTransform& gt, const std::string& srs_wkt,
                          const std::string& description) {
  // Colours as in the thesis's map views: occlusion red, c-set light grey, f-set dark grey.
  static const GDALColorEntry colours[kCellClassCount] = {
      {0, 0, 0, 0},         {255, 255, 255, 255}, {190, 210, 235, 255}, {220, 30, 30, 255},
      {215, 215, 215, 255}, {120, 120, 120, 255}, {20, 20, 20, 255}};
  write_atomically(path, [&](const std::filesystem::path& staged) {
    write_bands(path, staged, classes.rows(), classes.cols(), GDT_Byte, {classes.data()},
                {gt, srs_wkt, description}, [](GDALRasterBand& band) {
                  band.SetNoDataValue(0);
                  GDALColorTable table;
                  CPLStringList names;
                  for (int k = 0; k < kCellClassCount; ++k) {
                    table.SetColorEntry(k, &colours[k]);
                    names.AddString(cell_class_name(static_cast<CellClass>(k)));
                  }
                  band.SetColorTable(&table);
                  band.SetCategoryNames(names.List());
                });
  });
}

void write_visibility(const std::string& path, const Grid<std::uint8_t>& visibility,
                      const GeoTransform& gt, const std::string& srs_wkt,
                      const std::string& description) {
  // Hidden ground greyed, visible ground clear, beyond the range left out. The table reaches the
  // nodata value: a format that writes it as a PNG palette (GeoPackage tiles) refused an index
  // beyond the table.
  static const GDALColorEntry hidden = {60, 60, 60, 150}, visible = {255, 255, 255, 0},
                              none = {0, 0, 0, 0};
  write_atomically(path, [&](const std::filesystem::path& staged) {
    write_bands(path, staged, visibility.rows(), visibility.cols(), GDT_Byte, {visibility.data()},
                {gt, srs_wkt, description}, [](GDALRasterBand& band) {
                  band.SetNoDataValue(255);
                  GDALColorTable table;
                  table.SetColorEntry(0, &hidden);
                  table.SetColorEntry(1, &visible);
                  table.SetColorEntry(255, &none);
                  band.SetColorTable(&table);
                  const char* names[] = {"hidden", "visible", nullptr};
                  band.SetCategoryNames(const_cast<char**>(names));
                });
  });
}

}  // namespace tsk::io
