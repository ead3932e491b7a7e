// Stage 1 (SPEC 1.1): turn the DEM into the oriented grid g[p][i] seen by the viewer.
// Profiles p run left to right as the viewer sees them, cells i front to back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "grid.h"

namespace tsk {

// A DEM pixel position: column and row, continuous, cell (r, c) has its centre at (c+0.5, r+0.5).
struct PixelPoint {
  double col;
  double row;
};

// How oriented cells sit on the DEM. Cardinal views (0, 90, 180, 270) are exact flips: an integer
// map dem_row = row0 + row_per_p * p + row_per_i * i (likewise the column). Any other azimuth
// resamples the DEM onto a grid aligned with the line of sight (spacing min(dx, dy), bilinear).
// Both kinds keep the exact affine map to_pixel() from oriented positions to DEM pixels.
struct OrientedFrame {
  std::size_t profiles = 0;  // P
  std::size_t length = 0;    // L, cells per profile
  double d = 1.0;            // spacing along profiles, ground units
  double w = 1.0;            // spacing across profiles, ground units
  double azimuth_deg = 90;   // normalised to [0, 360)
  bool resampled = false;    // false: cardinal view, exact flip of the DEM
  std::size_t dem_rows = 0, dem_cols = 0;

  // Exact integer map, cardinal views only.
  std::int64_t row0 = 0, row_per_p = 0, row_per_i = 0;
  std::int64_t col0 = 0, col_per_p = 0, col_per_i = 0;

  // Affine map of oriented positions to DEM pixels, every view.
  double px_col0 = 0, px_col_per_p = 0, px_col_per_i = 0;
  double px_row0 = 0, px_row_per_p = 0, px_row_per_i = 0;

  std::size_t dem_row(std::size_t p, std::size_t i) const {
    return static_cast<std::size_t>(row0 + row_per_p * static_cast<std::int64_t>(p) +
                                    row_per_i * static_cast<std::int64_t>(i));
  }
  std::size_t dem_col(std::size_t p, std::size_t i) const {
    return static_cast<std::size_t>(col0 + col_per_p * static_cast<std::int64_t>(p) +
                                    col_per_i * static_cast<std::int64_t>(i));
  }
  // DEM pixel position of profile p at continuous position s along it (s = i at a cell centre).
  PixelPoint to_pixel(double p, double s) const {
    return {px_col0 + px_col_per_p * p + px_col_per_i * s,
            px_row0 + px_row_per_p * p + px_row_per_i * s};
  }
};

// True for the views that are exact flips of the DEM: azimuth 0, 90, 180 or 270 (modulo 360).
bool is_cardinal(double azimuth_deg);

// The frame for a DEM of rows x cols with cell sizes dx (east-west) and dy (north-south), row 0
// north, seen facing `azimuth_deg`. Exact for cardinal views, resampled otherwise. Throws Error
// for an empty grid, bad cell sizes or an oriented grid too large to address.
OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg);

// The resampled frame even at a cardinal azimuth (to compare the two paths).
OrientedFrame make_resampled_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                                   double azimuth_deg);

// Copies DEM rows [first_row, first_row + count) into their places in the oriented grid, so an
// adapter can read a raster block by block without holding the DEM twice. Cardinal frames only.
void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented);

// The whole DEM turned (cardinal) or resampled (any other azimuth: bilinear, nodata where a
// source cell with weight is nodata or outside the DEM).
HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame, unsigned threads = 0);

// Resamples profiles [first, first + count) of a resampled frame into `out` (rows = profiles),
// reusing its memory when it already has that shape: for streaming a view strip by strip.
void resample_profiles(const HeightGrid& dem, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads = 0);

// A window of DEM cells: rows [row0, row0 + rows) x columns [col0, col0 + cols), row 0 north.
struct DemWindow {
  std::size_t row0 = 0, col0 = 0, rows = 0, cols = 0;
};

// Reads a window of the DEM into `heights`: window.rows x window.cols, row by row, NaN for
// nodata. Throws Error when the raster cannot be read.
using WindowReader = std::function<void(const DemWindow& window, float* heights)>;

// Reads a DEM of rows x cols cells whole through `read`, top to bottom in blocks of rows of
// about 16 MB, handing each block to use(first_row, count, heights).
void read_row_blocks(
    std::size_t rows, std::size_t cols, const WindowReader& read,
    const std::function<void(std::size_t first_row, std::size_t count, const float* heights)>& use);

// The lowest height with data (finite; 0 when none) of a DEM of rows x cols cells read through
// `read` a block of rows at a time: the plan-oblique reference (SPEC 1.9) of a DEM read strip by
// strip, the same as OrientedGridBuilder::dem_lowest_height() gives when it is read whole.
double dem_lowest_height(std::size_t rows, std::size_t cols, const WindowReader& read);

// The DEM cells that the bilinear samples of profiles [first, first + count) of a resampled frame
// read, and few others: DEM rows [first_row, first_row + rows), each with its own run of columns
// (held with the columns of the runs of the rows read with it, at most an eighth more).
// A strip of a non-cardinal view lies diagonally on the DEM, so its bounding window can be the
// whole DEM; the band holds about as many cells as the strip.
class DemBand {
 public:
  // Lays out the band of profiles [first, first + count), reusing the memory of the previous one,
  // and reads it through `read`, a few rows at a time.
  void load(const OrientedFrame& frame, std::size_t first, std::size_t count,
            const WindowReader& read);

  // Profiles [first_profile, first_profile + profile_count) are the ones it was laid out for.
  std::size_t first_profile() const { return first_profile_; }
  std::size_t profile_count() const { return profile_count_; }
  std::size_t first_row() const { return first_row_; }
  std::size_t rows() const { return col_begin_.size(); }
  std::size_t cells() const { return heights_.size(); }
  // Columns [col_begin(k), col_end(k)) of DEM row first_row() + k are held; the heights of DEM
  // cell (r, c) are heights()[row_base(r - first_row()) + c].
  std::size_t col_begin(std::size_t k) const { return col_begin_[k]; }
  std::size_t col_end(std::size_t k) const { return col_end_[k]; }
  std::ptrdiff_t row_base(std::size_t k) const { return row_base_[k]; }
  const std::ptrdiff_t* row_bases() const { return row_base_.data(); }
  const float* heights() const { return heights_.data(); }

 private:
  std::size_t first_profile_ = 0, profile_count_ = 0;
  std::size_t first_row_ = 0;
  std::vector<std::size_t> col_begin_, col_end_;
  std::vector<std::ptrdiff_t> row_base_;
  std::vector<float, LargePageAllocator<float>> heights_;
};

// resample_profiles from the band of those profiles (DemBand::load), with the same heights;
// throws Error for profiles the band was not laid out for.
void resample_profiles(const DemBand& band, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads = 0);

// Loads strips of oriented profiles of any view from a DEM read window by window, for DEMs too
// large to hold whole: a cardinal view reads the window of its rows or columns and turns it, any
// other view reads the band its samples need and resamples it.
class StripLoader {
 public:
  StripLoader(const OrientedFrame& frame, WindowReader read, unsigned threads = 0);
  // Oriented profiles [first, first + count) into `strip`, whose memory may be reused.
  void load(std::size_t first, std::size_t count, HeightGrid& strip);

 private:
  OrientedFrame frame_;
  WindowReader read_;
  unsigned threads_;
  DemBand band_;       // resampled views
  HeightGrid window_;  // cardinal views but the one from the west, whose window is its strip
};

// Builds the oriented grid from DEM rows delivered block by block, top to bottom, as raster
// adapters read them: scattered straight into place for cardinal views, gathered into the whole
// DEM and resampled at the end for other azimuths.
class OrientedGridBuilder {
 public:
  explicit OrientedGridBuilder(const OrientedFrame& frame);
  void add_rows(std::size_t first_row, std::size_t count, const float* rows);
  HeightGrid finish(unsigned threads = 0);
  // The lowest height with data among the rows delivered (0 when none): the DEM's minimum, the
  // plan-oblique reference of SPEC 1.9. A resampled grid's own minimum may lie above it.
  double dem_lowest_height() const;

 private:
  const OrientedFrame& frame_;
  HeightGrid grid_;  // the oriented grid (cardinal) or the DEM (resampled)
  LowestHeight lowest_;
};

// The DEM window (rows or columns, by view) that holds oriented profiles [first, first + count)
// of a cardinal frame, for readers that load a DEM strip by strip.
DemWindow profile_window(const OrientedFrame& frame, std::size_t first, std::size_t count);

// Profiles [first, first + count) turned from their window (read as rows x cols, row 0 north)
// into `out`, reusing its memory when it has their shape.
void orient_window(const OrientedFrame& frame, const HeightGrid& window, HeightGrid& out);

// Bilinear height at a DEM pixel position; NaN outside the cell centres' hull or next to nodata.
float sample_bilinear(const HeightGrid& dem, PixelPoint px);

}  // namespace tsk
