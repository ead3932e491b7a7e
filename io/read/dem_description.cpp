#include "io/read/dem_description.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "core/base/parallel.h"
#include "core/method/slope_survey.h"
#include "io/read/dem_notes.h"
#include "io/read/gdal_util.h"

namespace tsk::io {
namespace {

void check_band(GDALDataset& dataset, const std::string& path, int band) {
  const int bands = dataset.GetRasterCount();
  if (bands < 1) throw Error("'" + path + "' has no raster bands");
  if (band < 1 || band > bands) {
    throw Error("band " + std::to_string(band) + " does not exist: '" + path + "' has " +
                std::to_string(bands) + " band(s)");
  }
  const GDALDataType type = dataset.GetRasterBand(band)->GetRasterDataType();
  if (GDALDataTypeIsComplex(type)) {
    throw Error("band " + std::to_string(band) + " of '" + path + "' holds complex numbers (" +
                GDALGetDataTypeName(type) + "); heights are real numbers");
  }
}

// GDAL's six numbers, for a message.
std::string geotransform_text(const double* gt) {
  std::string text;
  for (int k = 0; k < 6; ++k) text += (k ? ", " : "") + number_text(gt[k]);
  return text;
}

// The geotransform of a north-up DEM, or of square cells of the given size for a raster without
// georeferencing (with a note).
void read_georeferencing(GDALDataset& dataset, const std::string& path, const DemOptions& options,
                         Dem& dem) {
  double gt[6];
  const std::string warp = std::string("gdalwarp ") + kWarpNoData + " INPUT OUTPUT_northup.tif";
  if (dataset.GetGeoTransform(gt) == CE_None) {
    if (!std::all_of(gt, gt + 6, [](double v) { return std::isfinite(v); })) {
      throw Error("'" + path + "' has a geotransform that is not all finite numbers (" +
                  geotransform_text(gt) + "); set its corners, e.g. " + kSetCorners);
    }
    if (gt[2] != 0.0 || gt[4] != 0.0) {
      throw Error("'" + path +
                  "' has a rotated or sheared geotransform; make it north-up first, "
                  "e.g. " +
                  warp);
    }
    if (!(gt[1] > 0.0) || !(gt[5] < 0.0)) {
      throw Error("'" + path +
                  "' is not north-up (row 0 must be north, column 0 west); warp it "
                  "first, e.g. " +
                  warp);
    }
    std::copy(gt, gt + 6, dem.geotransform.a.begin());
    if (options.cell_size > 0.0)
      dem.notes.push_back({DemNoteCode::cell_size_ignored, {options.cell_size}, {}});
    return;
  }
  const int control_points = dataset.GetGCPCount();
  if (options.cell_size > 0.0) {
    dem.geotransform.a = {0.0, options.cell_size, 0.0, 0.0, 0.0, -options.cell_size};
    dem.notes.push_back({DemNoteCode::assumed_cell_size,
                         {options.cell_size, static_cast<double>(control_points)},
                         {}});
  } else if (control_points > 0) {
    // Told "no georeferencing", a user gave a cell size and got strokes in the grid's own frame.
    throw Error("'" + path + "' is placed by " + std::to_string(control_points) +
                " ground control points, not a geotransform: warp it by them first, e.g. "
                "gdalwarp " +
                kWarpNoData + " INPUT OUTPUT_warped.tif");
  } else {
    throw Error("'" + path +
                "' has no georeferencing, so its cell size is unknown; give it with --cell-size");
  }
}

// The DEM's centre in degrees of longitude and latitude, through the CRS's own geographic CRS.
bool centre_in_degrees(const OGRSpatialReference& srs, const Dem& dem, double& lon, double& lat) {
  dem.geotransform.apply({static_cast<double>(dem.cols) / 2, static_cast<double>(dem.rows) / 2},
                         lon, lat);
  if (srs.IsGeographic()) return true;
  std::unique_ptr<OGRSpatialReference> geographic(srs.CloneGeogCS());
  if (!geographic) return false;
  geographic->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference source(srs);
  source.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> to_lonlat(
      OGRCreateCoordinateTransformation(&source, geographic.get()));
  return to_lonlat && to_lonlat->Transform(1, &lon, &lat);
}

void add_crs_facts(const OGRSpatialReference& srs, const Dem& dem, DemFacts& f) {
  f.has_crs = true;
  f.geographic = srs.IsGeographic();
  const char* authority = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  f.crs_id = authority && code ? std::string(authority) + ":" + code : std::string(srs.GetName());
  const char* unit = nullptr;
  const double metres_per_unit = srs.GetLinearUnits(&unit);
  f.unit_is_metre = !(srs.IsProjected() && std::fabs(metres_per_unit - 1.0) > 1e-9);
  if (!f.unit_is_metre && unit) f.unit = unit;
  char* proj = nullptr;
  if (srs.exportToProj4(&proj) == OGRERR_NONE && proj) f.proj = proj;
  CPLFree(proj);
  f.has_centre = centre_in_degrees(srs, dem, f.centre_lon, f.centre_lat);
}

// A read of the range sample failed: told later, by the run's reads.
struct RangeReadFailed {};

// True when the reads take `v` for the declared nodata: they compare as floats (a declared
// -9999.9 is -9999.900390625 in a float), and a value beyond float's range is no float's.
bool read_as_nodata(double v, bool has_nodata, float nodata) {
  return has_nodata && std::fabs(v) <= std::numeric_limits<float>::max() &&
         static_cast<float>(v) == nodata;
}

// Widens [lowest, highest] to the values of `band`, nodata and NaN left out as the run's reads
// leave them out, in the even windows of `windows` that take(k) takes, until `stop` is set;
// throws when a read fails. Doubles, so that a fill value's note tells it as it is.
template <typename Take>
void range_of_windows(GDALRasterBand& band, const std::vector<DemWindow>& windows, Take&& take,
                      const std::atomic<bool>& stop, double& lowest, double& highest) {
  int has_nodata = 0;
  const auto nodata = static_cast<float>(band.GetNoDataValue(&has_nodata));
  std::vector<double> values;
  for (std::size_t k = 0; k < windows.size() && !stop; k += 2) {
    if (!take(k)) continue;
    const DemWindow& w = windows[k];
    values.resize(w.rows * w.cols);
    if (band.RasterIO(GF_Read, static_cast<int>(w.col0), static_cast<int>(w.row0),
                      static_cast<int>(w.cols), static_cast<int>(w.rows), values.data(),
                      static_cast<int>(w.cols), static_cast<int>(w.rows), GDT_Float64, 0, 0,
                      nullptr) != CE_None) {
      throw RangeReadFailed{};
    }
    for (const double v : values) {
      if (std::isnan(v) || read_as_nodata(v, has_nodata != 0, nodata)) continue;
      lowest = std::min(lowest, v), highest = std::max(highest, v);
    }
  }
}

// The band's least and greatest values, its nodata and NaN left out, among cells that the
// adaptive filter's survey reads (survey_windows: the whole of a small DEM, else 64 windows spread
// over it, each in a block of its own). Every other window: as many blocks as GDAL's approximate
// range read (32 of the 8000 x 8000 benchmark's 1024), so that a run without a survey reads no
// more than before, and a survey reads these from GDAL's cache rather than 32 others more. Given
// `second` (the band of the file opened once more), half of them are read through it on a thread
// of its own, those the survey reads through its second reader (read_alongside()), which finds
// them in its cache. False when no cell is valid, or a read fails (the failure is told later, by
// the run's reads, and stops the other reader at its next window).
bool sampled_range(GDALRasterBand& band, GDALRasterBand* second, double& lowest, double& highest) {
  const auto rows = static_cast<std::size_t>(band.GetYSize());
  const auto cols = static_cast<std::size_t>(band.GetXSize());
  const std::vector<DemWindow> windows = survey_windows(rows, cols);
  std::array<double, 2> low, high;
  low.fill(std::numeric_limits<double>::infinity()), high.fill(-low[0]);
  const bool two = second != nullptr;
  try {
    run_two_shares(two, [&](int share, const std::atomic<bool>& stop) {
      const bool alongside = share == 1;
      // The run's reads tell a failure; the caller's thread's last error stays for them to tell.
      std::optional<GdalErrorCapture> quiet;
      if (alongside) quiet.emplace();
      const auto take = [&](std::size_t k) { return reader_takes(k, two, alongside); };
      range_of_windows(alongside ? *second : band, windows, take, stop, low[share], high[share]);
    });
  } catch (const RangeReadFailed&) {
    return false;
  }
  lowest = std::min(low[0], low[1]), highest = std::max(high[0], high[1]);
  return lowest <= highest;
}

void add_value_facts(GDALRasterBand& band, GDALRasterBand* second, bool sample_range, DemFacts& f) {
  f.scale = band.GetScale();
  f.offset = band.GetOffset();
  if (sample_range) f.has_range = sampled_range(band, second, f.lowest_value, f.highest_value);
}

}  // namespace

Dem describe_dem(GDALDataset& dataset, const std::string& path, const DemOptions& options,
                 GDALDataset* second) {
  check_band(dataset, path, options.band);
  Dem dem;
  dem.rows = static_cast<std::size_t>(dataset.GetRasterYSize());
  dem.cols = static_cast<std::size_t>(dataset.GetRasterXSize());
  read_georeferencing(dataset, path, options, dem);
  DemFacts facts;
  facts.rows = dem.rows, facts.cols = dem.cols;
  facts.cell_x = dem.geotransform.a[1], facts.cell_y = -dem.geotransform.a[5];
  facts.west = dem.geotransform.a[0], facts.north = dem.geotransform.a[3];
  facts.bands = dataset.GetRasterCount(), facts.band = options.band;
  const GDALColorInterp colour = dataset.GetRasterBand(options.band)->GetColorInterpretation();
  facts.colour_band = colour == GCI_RedBand || colour == GCI_GreenBand || colour == GCI_BlueBand ||
                      colour == GCI_AlphaBand;
  const OGRSpatialReference* srs = dataset.GetSpatialRef();
  if (srs) add_crs_facts(*srs, dem, facts);
  add_value_facts(*dataset.GetRasterBand(options.band),
                  second ? second->GetRasterBand(options.band) : nullptr, options.sample_range,
                  facts);
  const DemAssessment assessment = assess_dem(facts);
  if (assessment.refused) throw DemRefused(path, assessment.notes.front());
  dem.ground_scale = assessment.ground_scale;
  dem.notes.insert(dem.notes.end(), assessment.notes.begin(), assessment.notes.end());
  if (srs) {
    char* wkt = nullptr;
    srs->exportToWkt(&wkt);
    dem.srs_wkt = wkt ? wkt : "";
    CPLFree(wkt);
  }
  const double dx = dem.geotransform.a[1] * dem.ground_scale;
  const double dy = -dem.geotransform.a[5] * dem.ground_scale;
  dem.grid = {dem.rows, dem.cols, dx, dy};
  make_frame(dem.grid, 90.0);  // refuses a grid no view could address, before any work
  return dem;
}

}  // namespace tsk::io
