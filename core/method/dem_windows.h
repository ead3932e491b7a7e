// Reading a DEM window by window, for adapters that read rasters: whole in blocks of rows, or
// strip by strip for DEMs too large to hold (the band of cells a resampled strip needs).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/base/grid.h"
#include "core/method/frame.h"

namespace tsk {

// A window of DEM cells: rows [row0, row0 + rows) x columns [col0, col0 + cols), row 0 north.
struct DemWindow {
  std::size_t row0 = 0, col0 = 0, rows = 0, cols = 0;
};

// Reads a window of the DEM into `heights`: window.rows x window.cols, row by row, NaN for
// nodata. Throws Error when the raster cannot be read.
using WindowReader = std::function<void(const DemWindow& window, float* heights)>;

// Copies `window` of a grid held in memory into `heights`, row by row (a WindowReader's work on
// a DEM held whole). Throws Error when the window does not lie in the grid.
void copy_window(const HeightGrid& grid, const DemWindow& window, float* heights);

// Reads a DEM of rows x cols cells whole through `read`, top to bottom in blocks of rows of
// about 16 MB, handing each block to use(first_row, count, heights).
void read_row_blocks(
    std::size_t rows, std::size_t cols, const WindowReader& read,
    const std::function<void(std::size_t first_row, std::size_t count, const float* heights)>& use);

// The lowest height with data (finite; 0 when none) of a DEM of rows x cols cells read through
// `read` a block of rows at a time: the plan-oblique reference (SPEC 1.9) of a DEM read strip by
// strip, the same as OrientedGridBuilder::dem_lowest_height() gives when it is read whole.
double dem_lowest_height(std::size_t rows, std::size_t cols, const WindowReader& read);

// The part of dem_lowest_height() of DEM rows [first_row, first_row + rows), for machines that each
// read a part: +infinity when none of them has data. The DEM's lowest height is the least of its
// parts' (0 when every part is +infinity), exactly as dem_lowest_height() finds it.
double lowest_height_of_rows(std::size_t first_row, std::size_t rows, std::size_t cols,
                             const WindowReader& read);

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

// A DEM read whole and turned for a view: its grid and the DEM's lowest height.
struct TurnedDem {
  HeightGrid oriented;
  double lowest_height = 0.0;
};

// Reads the DEM of `frame` whole through `read`, block of rows after block of rows, and turns it
// for the frame's view (OrientedGridBuilder). `rows_read` hears of the share of rows read (0 to
// 1) after each block. Throws what `read` throws.
TurnedDem turn_dem(const OrientedFrame& frame, const WindowReader& read,
                   const std::function<void(double)>& rows_read = {});

}  // namespace tsk
