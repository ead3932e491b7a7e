#include "io/read/dem_reader.h"

#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <new>
#include <thread>
#include <vector>

#include "core/base/parallel.h"
#include "core/method/silhouettes.h"
#include "core/method/slope_survey.h"
#include "io/read/block_retention.h"
#include "io/read/dem_description.h"
#include "io/read/gdal_util.h"

namespace tsk::io {
namespace {

// Replaces the band's nodata value, if it has one, and float's fill values by the core's NaN in
// `values`.
void nodata_to_nan(GDALRasterBand& band, float* values, std::size_t count) {
  int has_nodata = 0;
  const auto nodata = static_cast<float>(band.GetNoDataValue(&has_nodata));
  mark_nodata(values, count, has_nodata != 0, nodata);
}

// Reads windows of the band as Float32, nodata to NaN, the band's scale and offset applied (a DEM
// stored in decimetres as integers has scale 0.1), as QGIS applies them.
// `earlier_failure`, when given, is a failure GDAL reported on an earlier read of the band: GDAL
// tells a missing file behind a VRT once per thread, so a later read fails without a reason.
WindowReader band_reader(GDALRasterBand& band, const std::string& path,
                         std::shared_ptr<const std::string> earlier_failure = nullptr) {
  const double scale = band.GetScale(), offset = band.GetOffset();
  if (!std::isfinite(scale) || scale == 0.0 || !std::isfinite(offset)) {
    throw Error("'" + path + "' gives its band a scale of " + number_text(scale) +
                " and an offset of " + number_text(offset) +
                ", which make no heights; correct them (gdal_edit.py -scale 1 -offset 0 INPUT)");
  }
  return [&band, path, scale, offset, earlier_failure](const DemWindow& w, float* heights) {
    GdalErrorCapture errors;
    if (band.RasterIO(GF_Read, static_cast<int>(w.col0), static_cast<int>(w.row0),
                      static_cast<int>(w.cols), static_cast<int>(w.rows), heights,
                      static_cast<int>(w.cols), static_cast<int>(w.rows), GDT_Float32, 0,
                      0) != CE_None) {
      const bool unexplained =
          errors.first_failure().empty() && earlier_failure && !earlier_failure->empty();
      throw Error("reading '" + path +
                  "' failed: " + (unexplained ? *earlier_failure : errors.message()));
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

// `read` calling `stop` before each window it reads (`read` itself without one).
WindowReader stopping(WindowReader read, std::function<void()> stop) {
  if (!stop) return read;
  return [read = std::move(read), stop = std::move(stop)](const DemWindow& w, float* heights) {
    stop();
    read(w, heights);
  };
}

// Reads rows [from, to) of the DEM through `read` straight into `grid`, `step` rows at a time,
// noting their lowest height; gives up quietly once `given_up` is set (by the other half).
void read_rows_into(const WindowReader& read, std::size_t from, std::size_t to, std::size_t step,
                    const std::atomic<bool>& given_up, HeightGrid& grid, LowestHeight& lowest) {
  const std::size_t cols = grid.cols();
  for (std::size_t top = from; top < to && !given_up; top += step) {
    const std::size_t count = std::min(step, to - top);
    read({top, 0, count, cols}, grid.row(top));
    lowest.add(grid.row(top), count * cols);
  }
}

// A DEM that needs no turning is read straight into its grid, its two halves at once, each
// through a dataset of its own (a GDAL dataset is not to be shared between threads): the first
// touch of a DEM-sized grid's pages and the decoding of its blocks are most of a read.
void read_as_it_lies(const std::string& path, GDALRasterBand& band, const DemOptions& options,
                     Dem& dem) {
  HeightGrid grid(dem.rows, dem.cols, kUnset);
  // Reads of whole block rows, a few MB each, and halves that share no block: each block is
  // decoded once, whatever GDAL's cache holds.
  int block_width = 0, block_height = 0;
  band.GetBlockSize(&block_width, &block_height);
  const std::size_t block_rows = static_cast<std::size_t>(std::max(1, block_height));
  const std::size_t step =
      std::max<std::size_t>(1, (std::size_t{1} << 22) / dem.cols / block_rows) * block_rows;
  const std::size_t half =
      dem.rows >= 512 && std::thread::hardware_concurrency() > 1
          ? std::min(dem.rows, (dem.rows / 2 + block_rows - 1) / block_rows * block_rows)
          : dem.rows;
  LowestHeight upper, lower;
  run_two_shares(half < dem.rows, [&](int share, const std::atomic<bool>& stop) {
    if (share == 0) {
      read_rows_into(stopping(band_reader(band, path), options.stop), 0, half, step, stop, grid,
                     upper);
      return;
    }
    GdalErrorCapture capture;
    auto dataset = open_raster(path);
    read_rows_into(stopping(band_reader(*dataset->GetRasterBand(options.band), path), options.stop),
                   half, dem.rows, step, stop, grid, lower);
  });
  upper.add(lower);
  dem.lowest_height = upper.value();
  dem.oriented = std::move(grid);
}

// Reads the band in blocks of rows into dem.oriented.
void read_band(const std::string& path, GDALRasterBand& band, const DemOptions& options, Dem& dem) {
  if (dem.frame.as_it_lies()) return read_as_it_lies(path, band, options, dem);
  TurnedDem turned = turn_dem(dem.frame, stopping(band_reader(band, path), options.stop));
  dem.lowest_height = turned.lowest_height;
  dem.oriented = std::move(turned.oriented);
}

}  // namespace

Dem read_dem(const std::string& path, const DemOptions& options, double azimuth_deg) {
  GdalErrorCapture capture;
  auto dataset = open_raster(path);
  Dem dem = describe_dem(*dataset, path, options);
  refuse_too_large_to_turn(path, dem, azimuth_deg);
  dem.frame = make_frame(dem.grid, azimuth_deg);
  try {
    read_band(path, *dataset->GetRasterBand(options.band), options, dem);
  } catch (const std::bad_alloc&) {
    throw Error("not enough memory for a " + std::to_string(dem.rows) + " x " +
                std::to_string(dem.cols) + " DEM");
  }
  return dem;
}

void refuse_too_large_to_turn(const std::string& path, const Dem& dem, double azimuth_deg) {
  if (!too_large_to_turn_whole(make_frame(dem.grid, azimuth_deg))) return;
  throw Error("'" + path + "' (" + std::to_string(dem.cols) + " x " + std::to_string(dem.rows) +
              " cells) is too large for this command, which holds the whole DEM turned to the "
              "view: that would take more than half of this machine's memory. `silhouettes` "
              "reads large DEMs strip by strip, with its preview; or clip or resample the DEM");
}

void require_on_dem_grid(const std::string& path, const Dem& dem) {
  GdalErrorCapture capture;
  auto dataset = open_raster(path);
  const auto rows = static_cast<std::size_t>(dataset->GetRasterYSize());
  const auto cols = static_cast<std::size_t>(dataset->GetRasterXSize());
  if (rows != dem.rows || cols != dem.cols) {
    throw Error("'" + path + "' has " + std::to_string(cols) + " x " + std::to_string(rows) +
                " cells, the DEM " + std::to_string(dem.cols) + " x " + std::to_string(dem.rows) +
                ": it must lie on the DEM's grid (gdalwarp it with the DEM's -te and -tr)");
  }
  double gt[6];
  const std::array<double, 6>& d = dem.geotransform.a;
  const double cell = std::min(std::fabs(d[1]), std::fabs(d[5]));
  if (dataset->GetGeoTransform(gt) == CE_None) {
    for (int k = 0; k < 6; ++k) {
      if (std::fabs(gt[k] - d[static_cast<std::size_t>(k)]) <= 1e-6 * cell) continue;
      throw Error("'" + path + "' lies on another grid than the DEM: origin " + number_text(gt[0]) +
                  ", " + number_text(gt[3]) + " and cells " + number_text(gt[1]) + " x " +
                  number_text(-gt[5]) + " against the DEM's " + number_text(d[0]) + ", " +
                  number_text(d[3]) + " and " + number_text(d[1]) + " x " + number_text(-d[5]) +
                  ": gdalwarp it onto the DEM's grid first");
    }
  }
  const OGRSpatialReference* srs = dataset->GetSpatialRef();
  if (!srs || dem.srs_wkt.empty()) return;
  OGRSpatialReference dem_srs;
  if (dem_srs.importFromWkt(dem.srs_wkt.c_str()) != OGRERR_NONE || srs->IsSame(&dem_srs)) return;
  const char* name = srs->GetName();
  throw Error("'" + path + "' is in another CRS (" + (name ? name : "unnamed") +
              ") than the DEM (" + (dem_srs.GetName() ? dem_srs.GetName() : "unnamed") +
              "): gdalwarp it onto the DEM's grid and CRS first");
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
    : BandWindows(open_raster(path), path, band) {}

BandWindows::BandWindows(DatasetPtr dataset, const std::string& path, int band)
    : dataset_(std::move(dataset)) {
  if (band < 1 || band > dataset_->GetRasterCount()) {
    throw Error("band " + std::to_string(band) + " does not exist in '" + path + "'");
  }
  band_ = dataset_->GetRasterBand(band);
  read_ = band_reader(*band_, path, earlier_failure_);
  rows_ = static_cast<std::size_t>(dataset_->GetRasterYSize());
  cols_ = static_cast<std::size_t>(dataset_->GetRasterXSize());
  int block_width = 0, block_height = 0;
  band_->GetBlockSize(&block_width, &block_height);
  block_rows_ = static_cast<std::size_t>(std::max(1, block_height));
  GDALRasterBand* band_to_drop = band_;
  retention_ = std::make_unique<BlockRetention>(
      rows_, cols_, block_rows_, static_cast<std::size_t>(std::max(1, block_width)),
      [band_to_drop](std::size_t x, std::size_t y) {
        band_to_drop->FlushBlock(static_cast<int>(x), static_cast<int>(y), FALSE);
      });
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
    read_({top, window.col0, run_end - top, window.cols},
          heights + (top - window.row0) * window.cols);
    retention_->read(top, run_end, window.col0, window.cols);
    // The next strip of a cardinal view starts on the row before this one's last.
    retention_->let_go_above((run_end - std::min<std::size_t>(run_end, 2)) / block_rows_);
    top = run_end;
  }
}

DemRefused::DemRefused(const std::string& path, DemNote note)
    : Error("'" + path + "' cannot be taken as it is"), path_(path), note_(std::move(note)) {}

namespace {

// The file of `first` opened once more, for the second reader of its range's sample and of the
// filter's survey, or null: only when the range is sampled over windows the two readers share (a
// DEM of up to about two million cells is one window; window 2 is the first read_alongside()
// names). A second opening that fails leaves one reader, as before.
DatasetPtr second_dataset(GDALDataset& first, const std::string& path, const DemOptions& options) {
  const std::size_t windows = survey_window_count(static_cast<std::size_t>(first.GetRasterYSize()),
                                                  static_cast<std::size_t>(first.GetRasterXSize()));
  if (!options.sample_range || windows <= 2) return nullptr;
  try {
    return open_raster(path);
  } catch (const Error&) {
    return nullptr;
  }
}

}  // namespace

// A file is opened twice when its range is sampled: the sample and the filter's survey read half
// their windows through each, on two threads (0.05 s each on one, at every DEM size).
DemFile::DemFile(const std::string& path, const DemOptions& options)
    : DemFile(open_raster(path), path, options, true) {}

DemFile::DemFile(DatasetPtr dataset, const std::string& path, const DemOptions& options)
    : DemFile(std::move(dataset), path, options, false) {}

DemFile::DemFile(DatasetPtr dataset, const std::string& path, const DemOptions& options,
                 bool reopen) {
  GdalErrorCapture capture;
  DatasetPtr second = reopen ? second_dataset(*dataset, path, options) : nullptr;
  dem_ = describe_dem(*dataset, path, options, second.get());
  file_ = std::make_unique<BandWindows>(std::move(dataset), path, options.band);
  if (second) alongside_ = std::make_unique<BandWindows>(std::move(second), path, options.band);
  // Describing it reads a sample of the DEM; a failure there is the reason for later ones.
  file_->remember_failure(capture.first_failure());
  stop_ = options.stop;
}

DemFile::~DemFile() = default;

DemSource DemFile::source() const {
  const auto reader = [this](const BandWindows& file) {
    return stopping([&file](const DemWindow& w, float* heights) { file.read(w, heights); }, stop_);
  };
  return {dem_.grid, dem_.geotransform, reader(*file_),
          alongside_ ? reader(*alongside_) : WindowReader()};
}

HeldDem HeldDemFile::held() const {
  DemSource source{dem.grid, dem.geotransform, windows ? windows->source().read : WindowReader()};
  return {dem.oriented, dem.frame, std::move(source), dem.lowest_height, dem.ground_scale};
}

HeldDemFile hold_dem(const std::string& path, const DemOptions& options, double azimuth_deg) {
  HeldDemFile held{read_dem(path, options, azimuth_deg), nullptr};
  if (!held.dem.frame.as_it_lies()) held.windows = std::make_unique<DemFile>(path, options);
  return held;
}

}  // namespace tsk::io
