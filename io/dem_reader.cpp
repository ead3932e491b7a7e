#include "dem_reader.h"

#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <new>
#include <vector>

#include "gdal_util.h"
#include "silhouettes.h"

namespace tsk::io {
namespace {

// Warped, a DEM gains cells around its own; without a nodata value they would be 0, and their
// edge a cliff in every view.
constexpr char kWarpNoData[] = "-dstnodata -9999";

// A reprojection hint for a geographic DEM: the UTM zone of its centre.
std::string utm_hint(const GeoTransform& gt, std::size_t rows, std::size_t cols) {
  double lon = 0, lat = 0;
  gt.apply({static_cast<double>(cols) / 2, static_cast<double>(rows) / 2}, lon, lat);
  const int zone = std::clamp(static_cast<int>(std::floor((lon + 180.0) / 6.0)) + 1, 1, 60);
  const int epsg = (lat >= 0 ? 32600 : 32700) + zone;
  return "gdalwarp -t_srs EPSG:" + std::to_string(epsg) + " -r bilinear " + kWarpNoData +
         " INPUT OUTPUT_utm.tif";
}

// Ground metres per map unit at the DEM's centre: cos(latitude) for Mercator projections (Web
// Mercator among them), whose map units grow away from the equator; 1 otherwise.
double mercator_ground_scale(const OGRSpatialReference& srs, const GeoTransform& gt,
                             std::size_t rows, std::size_t cols) {
  const char* projection = srs.GetAttrValue("PROJECTION");
  const bool mercator = projection &&
                        std::string(projection).find("Mercator") != std::string::npos &&
                        std::string(projection).find("Transverse") == std::string::npos;
  if (!mercator) return 1.0;
  std::unique_ptr<OGRSpatialReference> geographic(srs.CloneGeogCS());
  if (!geographic) return 1.0;
  geographic->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference source(srs);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> to_lonlat(
      OGRCreateCoordinateTransformation(&source, geographic.get()));
  double x = 0, y = 0;
  gt.apply({static_cast<double>(cols) / 2, static_cast<double>(rows) / 2}, x, y);
  if (!to_lonlat || !to_lonlat->Transform(1, &x, &y)) return 1.0;
  return std::cos(y * M_PI / 180.0);
}

// Replaces the band's nodata value, if it has one, by the core's NaN in `values`.
void nodata_to_nan(GDALRasterBand& band, float* values, std::size_t count) {
  int has_nodata = 0;
  const auto nodata = static_cast<float>(band.GetNoDataValue(&has_nodata));
  if (has_nodata) std::replace(values, values + count, nodata, kNoData);
}

// Reads windows of the band as Float32, nodata to NaN, the band's scale and offset applied (a DEM
// stored in decimetres as integers has scale 0.1), as QGIS applies them.
WindowReader band_reader(GDALRasterBand& band, const std::string& path) {
  const double scale = band.GetScale(), offset = band.GetOffset();
  if (!std::isfinite(scale) || scale == 0.0 || !std::isfinite(offset)) {
    throw Error("'" + path + "' gives its band a scale of " + number_text(scale) +
                " and an offset of " + number_text(offset) +
                ", which make no heights; correct them (gdal_edit.py -scale 1 -offset 0 INPUT)");
  }
  return [&band, path, scale, offset](const DemWindow& w, float* heights) {
    GdalErrorCapture errors;
    if (band.RasterIO(GF_Read, static_cast<int>(w.col0), static_cast<int>(w.row0),
                      static_cast<int>(w.cols), static_cast<int>(w.rows), heights,
                      static_cast<int>(w.cols), static_cast<int>(w.rows), GDT_Float32, 0,
                      0) != CE_None) {
      throw Error("reading '" + path + "' failed: " + errors.message());
    }
    const std::size_t count = w.rows * w.cols;
    nodata_to_nan(band, heights, count);
    if (scale != 1.0 || offset != 0.0) {
      // Heights out of float's range become infinite, which the core takes as nodata.
      for (std::size_t k = 0; k < count; ++k)
        heights[k] = static_cast<float>(static_cast<double>(heights[k]) * scale + offset);
    }
  };
}

// Reads the band in blocks of rows into dem.oriented.
void read_band(const std::string& path, GDALRasterBand& band, Dem& dem) {
  OrientedGridBuilder builder(dem.frame);
  read_row_blocks(dem.rows, dem.cols, band_reader(band, path),
                  [&builder](std::size_t first_row, std::size_t count, const float* heights) {
                    builder.add_rows(first_row, count, heights);
                  });
  dem.lowest_height = builder.dem_lowest_height();
  dem.oriented = builder.finish();
}

// Checks the band and the georeferencing of an open DEM and fills everything but the heights.
Dem describe_dem(GDALDataset& dataset, const std::string& path, const DemOptions& options) {
  const int bands = dataset.GetRasterCount();
  if (bands < 1) throw Error("'" + path + "' has no raster bands");
  if (options.band < 1 || options.band > bands) {
    throw Error("band " + std::to_string(options.band) + " does not exist: '" + path + "' has " +
                std::to_string(bands) + " band(s)");
  }
  Dem dem;
  dem.rows = static_cast<std::size_t>(dataset.GetRasterYSize());
  dem.cols = static_cast<std::size_t>(dataset.GetRasterXSize());

  double gt[6];
  if (dataset.GetGeoTransform(gt) == CE_None) {
    if (gt[2] != 0.0 || gt[4] != 0.0) {
      throw Error("'" + path +
                  "' has a rotated or sheared geotransform; make it north-up first, e.g. "
                  "gdalwarp " +
                  kWarpNoData + " INPUT OUTPUT_northup.tif");
    }
    if (!(gt[1] > 0.0) || !(gt[5] < 0.0)) {
      throw Error("'" + path +
                  "' is not north-up (row 0 must be north, column 0 west); warp it first, e.g. "
                  "gdalwarp " +
                  kWarpNoData + " INPUT OUTPUT_northup.tif");
    }
    std::copy(gt, gt + 6, dem.geotransform.a.begin());
  } else if (options.cell_size > 0.0) {
    dem.geotransform.a = {0.0, options.cell_size, 0.0, 0.0, 0.0, -options.cell_size};
    dem.notes +=
        "no georeferencing: cells taken as " + number_text(options.cell_size) + " m squares\n";
  } else {
    throw Error("'" + path +
                "' has no georeferencing, so its cell size is unknown; give it with --cell-size");
  }

  if (const OGRSpatialReference* srs = dataset.GetSpatialRef()) {
    if (srs->IsGeographic()) {
      throw Error("'" + path +
                  "' is in a geographic CRS: its cell sizes are degrees, not metres like its "
                  "heights. Reproject it to a metric CRS first, e.g. " +
                  utm_hint(dem.geotransform, dem.rows, dem.cols));
    }
    dem.ground_scale = mercator_ground_scale(*srs, dem.geotransform, dem.rows, dem.cols);
    if (dem.ground_scale != 1.0) {
      dem.notes +=
          "Mercator projection: map units are not ground metres here; cell sizes scaled by "
          "cos(latitude of the centre) = " +
          number_text(dem.ground_scale) + "\n";
    }
    if (srs->IsProjected() && std::fabs(srs->GetLinearUnits() - 1.0) > 1e-9) {
      dem.notes += "the CRS's linear unit is not the metre; heights must be in that same unit\n";
    }
    char* wkt = nullptr;
    srs->exportToWkt(&wkt);
    dem.srs_wkt = wkt ? wkt : "";
    CPLFree(wkt);
  } else {
    dem.notes += "no CRS: coordinates are written without one, cell sizes taken as metres\n";
  }

  // GDAL's approximate minimum reads a sample of the blocks: milliseconds, and fill values cover
  // whole holes and edges when they are there.
  double range[2];
  GDALRasterBand& band = *dataset.GetRasterBand(options.band);
  const double scale = band.GetScale(), offset = band.GetOffset();
  CPLErrorReset();
  GDALComputeRasterMinMax(&band, TRUE, range);
  const bool have_range = CPLGetLastErrorType() < CE_Failure;
  if (have_range && is_common_fill_value(range[0])) {
    dem.notes += "heights go down to " + number_text(range[0]) +
                 ", a common fill value: if those cells have no data, declare it as nodata "
                 "(gdal_edit.py -a_nodata " +
                 number_text(range[0]) + " INPUT)\n";
  } else if (have_range) {
    const double relief = std::fabs(scale) * (range[1] - range[0]);
    const double across = std::max(static_cast<double>(dem.cols) * dem.geotransform.a[1],
                                   static_cast<double>(dem.rows) * -dem.geotransform.a[5]) *
                          dem.ground_scale;
    if (implausible_relief(relief, across)) {
      dem.notes += "heights span " + number_text(relief) + " over a DEM " + number_text(across) +
                   " across, more than any terrain: if they are millimetres or centimetres, "
                   "give the band a scale (gdal_edit.py -scale 0.001 INPUT)\n";
    }
  }

  if (scale != 1.0 || offset != 0.0) {
    dem.notes += "heights are the band's values x " + number_text(scale) + " + " +
                 number_text(offset) + ", its scale and offset\n";
  }

  const double dx = dem.geotransform.a[1] * dem.ground_scale;
  const double dy = -dem.geotransform.a[5] * dem.ground_scale;
  dem.frame = make_frame(dem.rows, dem.cols, dx, dy, options.azimuth_deg);
  return dem;
}

}  // namespace

Dem read_dem(const std::string& path, const DemOptions& options) {
  GdalErrorCapture capture;
  auto dataset = open_raster(path);
  Dem dem = describe_dem(*dataset, path, options);
  refuse_too_large_to_turn(path, dem);
  try {
    read_band(path, *dataset->GetRasterBand(options.band), dem);
  } catch (const std::bad_alloc&) {
    throw Error("not enough memory for a " + std::to_string(dem.rows) + " x " +
                std::to_string(dem.cols) + " DEM");
  }
  return dem;
}

void refuse_too_large_to_turn(const std::string& path, const Dem& dem) {
  if (!too_large_to_turn_whole(dem.frame)) return;
  throw Error("'" + path + "' (" + std::to_string(dem.cols) + " x " + std::to_string(dem.rows) +
              " cells) is too large for this command, which holds the whole DEM turned to the "
              "view: that would take more than half of this machine's memory. `silhouettes` "
              "without `--preview` reads large DEMs strip by strip; or clip or resample the DEM");
}

std::vector<HeightGrid> read_bands(const std::string& path) {
  GdalErrorCapture capture;
  auto dataset = open_raster(path);
  const auto rows = static_cast<std::size_t>(dataset->GetRasterYSize());
  const auto cols = static_cast<std::size_t>(dataset->GetRasterXSize());
  std::vector<HeightGrid> bands;
  for (int b = 1; b <= dataset->GetRasterCount(); ++b) {
    HeightGrid grid(rows, cols, kUnset);
    band_reader(*dataset->GetRasterBand(b), path)({0, 0, rows, cols}, grid.data());
    bands.push_back(std::move(grid));
  }
  return bands;
}

BandWindows::BandWindows(const std::string& path, int band)
    : BandWindows(
          [&] {
            GdalErrorCapture capture;
            return open_raster(path);
          }(),
          path, band) {}

BandWindows::BandWindows(DatasetPtr dataset, const std::string& path, int band)
    : dataset_(std::move(dataset)) {
  if (band < 1 || band > dataset_->GetRasterCount()) {
    throw Error("band " + std::to_string(band) + " does not exist in '" + path + "'");
  }
  band_ = dataset_->GetRasterBand(band);
  read_ = band_reader(*band_, path);
  rows_ = static_cast<std::size_t>(dataset_->GetRasterYSize());
  cols_ = static_cast<std::size_t>(dataset_->GetRasterXSize());
  int block_width = 0, block_height = 0;
  band_->GetBlockSize(&block_width, &block_height);
  block_rows_ = static_cast<std::size_t>(std::max(1, block_height));
  blocks_per_row_ = (cols_ + static_cast<std::size_t>(std::max(1, block_width)) - 1) /
                    static_cast<std::size_t>(std::max(1, block_width));
  // At least 64 rows a run, so that a file of one-row blocks is not read row by row.
  run_rows_ = block_rows_ * ((64 + block_rows_ - 1) / block_rows_);
}

BandWindows::~BandWindows() = default;

bool BandWindows::geotransform(GeoTransform& gt) const {
  return dataset_->GetGeoTransform(gt.a.data()) == CE_None;
}

void BandWindows::read(const DemWindow& window, float* heights) const {
  const std::size_t end = window.row0 + window.rows;
  for (std::size_t top = window.row0; top < end;) {
    const std::size_t run_end = std::min(end, (top / run_rows_ + 1) * run_rows_);
    cached_from_ = std::min(cached_from_, top / block_rows_);
    read_({top, window.col0, run_end - top, window.cols},
          heights + (top - window.row0) * window.cols);
    // The next strip of a cardinal view starts on the row before this one's last.
    drop_block_rows_above((run_end - std::min<std::size_t>(run_end, 2)) / block_rows_);
    top = run_end;
  }
}

void BandWindows::drop_block_rows_above(std::size_t keep) const {
  for (; cached_from_ < keep; ++cached_from_) {
    for (std::size_t x = 0; x < blocks_per_row_; ++x)
      band_->FlushBlock(static_cast<int>(x), static_cast<int>(cached_from_), FALSE);
  }
}

DemFile::DemFile(const std::string& path, const DemOptions& options) {
  GdalErrorCapture capture;
  DatasetPtr dataset = open_raster(path);
  dem_ = describe_dem(*dataset, path, options);
  file_ = std::make_unique<BandWindows>(std::move(dataset), path, options.band);
}

DemFile::~DemFile() = default;

DemSource DemFile::source() const {
  return {dem_.frame, dem_.geotransform,
          [&file = *file_](const DemWindow& w, float* heights) { file.read(w, heights); }};
}

}  // namespace tsk::io
