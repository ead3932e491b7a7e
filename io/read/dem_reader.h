// Reads a DEM through GDAL straight into the core's oriented grid, with its georeferencing.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/method/orient.h"
#include "core/method/run_recipes.h"
#include "core/method/silhouettes.h"
#include "core/method/strokes.h"
#include "io/read/dem_notes.h"
#include "io/read/gdal_util.h"

namespace tsk::io {

class BlockRetention;

struct DemOptions {
  int band = 1;
  double cell_size = 0.0;  // > 0: use this cell size when the raster has no georeferencing
  // Called before every read of the DEM's cells (a few rows at a time); throws to stop a read
  // in any phase (the command line's Ctrl-C and SIGTERM). A DEM read whole on its own grid is
  // read on two threads, each calling it.
  std::function<void()> stop;
  // Whether describing the DEM reads a sample of its blocks for the band's range, which only the
  // notes on fill values and implausible relief need: a cluster's task, whose notes the client
  // has already told, opens the file without it (a thirtieth of a second on the 8000^2
  // benchmark's GeoTIFF, at every one of a run's tasks).
  bool sample_range = true;
};

struct Dem {
  HeightGrid oriented;
  DemGrid grid;         // the DEM's own grid, in ground units
  OrientedFrame frame;  // read_dem: the view it was turned for
  GeoTransform geotransform;
  std::string srs_wkt;         // empty when the raster has no CRS
  double ground_scale = 1.0;   // ground metres per map unit used for the cell sizes
  std::vector<DemNote> notes;  // what the user should know (no CRS, assumed units, ...)
  std::size_t rows = 0, cols = 0;
  double lowest_height = 0;  // the DEM's lowest height, the plan-oblique reference (SPEC 1.9)
};

// Warped, a DEM gains cells around its own; without a nodata value they would be 0, and their
// edge a cliff in every view: the gdalwarp hints pass this.
inline constexpr char kWarpNoData[] = "-dstnodata -9999";
// The command that places a DEM whose georeferencing is wrong: its corners set anew.
inline constexpr char kSetCorners[] = "gdal_edit.py -a_ullr WEST NORTH EAST SOUTH INPUT";

// A DEM the method cannot take as it is (a geographic CRS, whose cell sizes are degrees): the
// note says why, for the front end to word.
class DemRefused : public Error {
 public:
  DemRefused(const std::string& path, DemNote note);
  const std::string& path() const { return path_; }
  const DemNote& note() const { return note_; }

 private:
  std::string path_;
  DemNote note_;
};

// Throws tsk::Error with a message for the user on anything it cannot read faithfully:
// not a raster, bad band, rotated or south-up georeferencing, a geographic CRS.
// The DEM is turned for the view facing `azimuth_deg` (the run's ViewParams::azimuth_deg).
Dem read_dem(const std::string& path, const DemOptions& options, double azimuth_deg);

// Windows of one band of a raster file read as Float32, nodata as NaN, through a dataset of its
// own. The QGIS plugin reads a GDAL layer's file through it rather than through the layer's
// provider, which copies every block once more and leaves what it read in GDAL's process-wide
// block cache (a share of the machine's memory in QGIS, so a whole large DEM). Readers go down
// the DEM, strip by strip or band by band, so this one lets GDAL drop the blocks above the last
// rows read as it goes, but for those the next band will read again (BlockRetention): GDAL keeps
// about a run of block rows and a few blocks a block row, whatever its cache's size.
// One thread at a time.
class BandWindows {
 public:
  // Throws Error when `path` cannot be opened as a raster or has no band `band`.
  BandWindows(const std::string& path, int band);
  // Band `band` of `dataset`, opened from `path`.
  BandWindows(DatasetPtr dataset, const std::string& path, int band);
  ~BandWindows();
  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  // The file's geotransform; false when it has none.
  bool geotransform(GeoTransform& gt) const;
  // Throws Error with GDAL's message when the read fails.
  void read(const DemWindow& window, float* heights) const;
  // A failure GDAL reported on an earlier read of the band, given as the reason of a read that
  // fails without one.
  void remember_failure(const std::string& message) { *earlier_failure_ = message; }

 private:
  DatasetPtr dataset_;
  std::shared_ptr<std::string> earlier_failure_ = std::make_shared<std::string>();
  GDALRasterBand* band_;
  WindowReader read_;
  std::size_t rows_, cols_;
  std::size_t block_rows_ = 1;
  std::size_t run_rows_ = 1;  // windows are read in runs of rows ending on these multiples
  std::unique_ptr<BlockRetention> retention_;
};

// A DEM file open for a view, read window by window through BandWindows (so GDAL's cache holds
// about two rows of blocks): the source that sketch_silhouettes reads strip by strip, for DEMs of
// any size. Throws Error as read_dem does on anything it cannot read faithfully.
class DemFile {
 public:
  DemFile(const std::string& path, const DemOptions& options);
  // An open dataset (memory_raster.h), named in messages as `name`.
  DemFile(DatasetPtr dataset, const std::string& name, const DemOptions& options);
  ~DemFile();
  const Dem& info() const { return dem_; }  // grid, georeferencing and notes; no heights, no frame
  // The DEM for the core; it reads through this object, which must outlive it. A file whose range
  // was sampled has a second reader (DemSource::read_alongside), through a dataset of its own.
  DemSource source() const;

 private:
  // `reopen`: whether the file at `name` may be opened once more for a second reader.
  DemFile(DatasetPtr dataset, const std::string& name, const DemOptions& options, bool reopen);
  Dem dem_;
  std::unique_ptr<BandWindows> file_;
  std::unique_ptr<BandWindows> alongside_;  // the second reader, or null
  std::function<void()> stop_;
};

// A DEM read whole for its view (read_dem), with its file open for the filter's survey when the
// view turns the grid (as it lies, the survey reads the grid): what the recipes of
// run_recipes.h take, through held().
struct HeldDemFile {
  Dem dem;
  std::unique_ptr<DemFile> windows;  // null when the grid is the DEM as it lies
  HeldDem held() const;
};
HeldDemFile hold_dem(const std::string& path, const DemOptions& options, double azimuth_deg);

// Throws Error when the DEM of `path` described by `dem` could not be turned whole for the view
// facing `azimuth_deg` (too_large_to_turn_whole): what every command but `silhouettes` needs.
void refuse_too_large_to_turn(const std::string& path, const Dem& dem, double azimuth_deg);

// Throws Error, with the figures, unless the raster at `path` lies on the grid of `dem`: its size,
// and, when both are georeferenced, its origin and cell size (within a millionth of a cell) and
// CRS. A raster to drape on another grid was draped silently onto the wrong ground.
void require_on_dem_grid(const std::string& path, const Dem& dem);

// Every band of a raster as grids on its own pixel grid (row 0 north), nodata as NaN: the
// rasters to drape.
std::vector<HeightGrid> read_bands(const std::string& path);

}  // namespace tsk::io
