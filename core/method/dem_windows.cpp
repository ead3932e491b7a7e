#include "core/method/dem_windows.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "core/base/errors.h"
#include "core/base/release_storage.h"
#include "core/method/orient.h"
#include "core/method/resample.h"

namespace tsk {
namespace {

// The least and greatest x of the convex polygon `corners` within the rows y0 <= y <= y1; empty
// (lo > hi) when the polygon does not reach them.
std::pair<double, double> x_range_in_rows(const PixelPoint (&corners)[4], double y0, double y1) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto take = [&](double x) { lo = std::min(lo, x), hi = std::max(hi, x); };
  for (std::size_t k = 0; k < 4; ++k) {
    const PixelPoint a = corners[k], b = corners[(k + 1) % 4];
    if (a.row >= y0 && a.row <= y1) take(a.col);
    if (a.row == b.row) continue;
    for (const double y : {y0, y1}) {
      const double t = (y - a.row) / (b.row - a.row);
      if (t >= 0 && t <= 1) take(a.col + t * (b.col - a.col));
    }
  }
  return {lo, hi};
}

// floor(x) clamped to [0, limit], for positions that may lie far outside the DEM.
std::size_t clamped_floor(double x, std::size_t limit) {
  return static_cast<std::size_t>(std::clamp(std::floor(x), 0.0, static_cast<double>(limit)));
}

}  // namespace

void DemBand::load(const OrientedFrame& frame, std::size_t first, std::size_t count,
                   const WindowReader& read) {
  if (!frame.resampled || count == 0 || first > frame.profiles || count > frame.profiles - first)
    throw Error("the profiles do not match the resampled frame");
  first_profile_ = first, profile_count_ = count;
  // The samples of the strip fill a parallelogram of pixel positions. A sample at row position y
  // reads DEM rows floor(y - 0.5) and the next, so DEM row r is read from y in [r - 0.5, r + 1.5];
  // likewise columns. A margin of one cell more on every side absorbs rounding.
  constexpr double kMargin = 1.0;
  const auto p0 = static_cast<double>(first), p1 = static_cast<double>(first + count - 1);
  const auto s1 = static_cast<double>(frame.length - 1);
  const PixelPoint corners[4] = {frame.to_pixel(p0, 0), frame.to_pixel(p1, 0),
                                 frame.to_pixel(p1, s1), frame.to_pixel(p0, s1)};
  double y_min = corners[0].row, y_max = corners[0].row;
  for (const PixelPoint& c : corners)
    y_min = std::min(y_min, c.row), y_max = std::max(y_max, c.row);
  first_row_ = clamped_floor(std::ceil(y_min - 1.5 - kMargin), frame.dem_rows);
  const std::size_t end_row = clamped_floor(y_max + 0.5 + kMargin + 1, frame.dem_rows);
  const std::size_t rows = end_row > first_row_ ? end_row - first_row_ : 0;
  col_begin_.resize(rows), col_end_.resize(rows), row_base_.resize(rows);
  for (std::size_t k = 0; k < rows; ++k) {
    const auto r = static_cast<double>(first_row_ + k);
    const auto [x_lo, x_hi] = x_range_in_rows(corners, r - 0.5 - kMargin, r + 1.5 + kMargin);
    const std::size_t begin = clamped_floor(x_lo - 1.5 - kMargin, frame.dem_cols);
    const std::size_t end =
        x_lo <= x_hi ? clamped_floor(x_hi + 0.5 + kMargin + 1, frame.dem_cols) : 0;
    col_begin_[k] = begin;
    col_end_[k] = std::max(begin, end);
  }
  // Rows are read a few at a time, each chunk as the window spanning their runs, straight into
  // the band: a row holds the window's columns. A chunk grows while its window stays within an
  // eighth more than its widest run (a diagonal band's runs shift from row to row).
  constexpr std::size_t kMostChunkRows = 64;
  struct Chunk {
    std::size_t k0, k1, c0, c1, offset;
  };
  std::vector<Chunk> chunks;
  std::size_t cells = 0;
  for (std::size_t k0 = 0; k0 < rows;) {
    Chunk chunk{k0, k0 + 1, col_begin_[k0], col_end_[k0], cells};
    std::size_t widest = col_end_[k0] - col_begin_[k0];
    while (chunk.k1 < rows && chunk.k1 - k0 < kMostChunkRows) {
      const std::size_t k = chunk.k1;
      const std::size_t c0 = std::min(chunk.c0, col_begin_[k]);
      const std::size_t c1 = std::max(chunk.c1, col_end_[k]);
      const std::size_t run = std::max(widest, col_end_[k] - col_begin_[k]);
      if ((c1 - c0) * 8 > run * 9) break;
      chunk.c0 = c0, chunk.c1 = c1, widest = run, ++chunk.k1;
    }
    const std::size_t width = chunk.c1 - chunk.c0;
    for (std::size_t k = chunk.k0; k < chunk.k1; ++k) {
      row_base_[k] = static_cast<std::ptrdiff_t>(cells + (k - chunk.k0) * width) -
                     static_cast<std::ptrdiff_t>(chunk.c0);
    }
    cells += (chunk.k1 - chunk.k0) * width;
    chunks.push_back(chunk);
    k0 = chunk.k1;
  }
  if (cells > heights_.capacity()) {
    // A band holds about as many DEM cells as its strip covers, and the strips across the middle
    // of the DEM cover the most: room for those from the start, rather than growing band by band
    // into fresh memory (each page of it a fault), copying what is to be overwritten.
    const double cells_per_sample =
        std::abs(frame.px_col_per_i * frame.px_row_per_p - frame.px_row_per_i * frame.px_col_per_p);
    const double largest =
        std::min(cells_per_sample * static_cast<double>(count) * static_cast<double>(frame.length),
                 static_cast<double>(frame.dem_rows) * static_cast<double>(frame.dem_cols));
    release_storage(heights_);  // before the larger block is taken, not after
    heights_.reserve(std::max(cells, static_cast<std::size_t>(1.125 * largest)));
  }
  heights_.resize(cells);
  for (const Chunk& chunk : chunks) {
    if (chunk.c0 >= chunk.c1) continue;
    read({first_row_ + chunk.k0, chunk.c0, chunk.k1 - chunk.k0, chunk.c1 - chunk.c0},
         heights_.data() + chunk.offset);
  }
}

void copy_window(const HeightGrid& grid, const DemWindow& w, float* heights) {
  if (w.row0 > grid.rows() || w.rows > grid.rows() - w.row0 || w.col0 > grid.cols() ||
      w.cols > grid.cols() - w.col0)
    throw Error("internal: a window beyond the DEM held");
  for (std::size_t r = 0; r < w.rows; ++r) {
    const float* row = grid.row(w.row0 + r) + w.col0;
    std::copy(row, row + w.cols, heights + r * w.cols);
  }
}

void read_row_blocks(std::size_t rows, std::size_t cols, const WindowReader& read,
                     const std::function<void(std::size_t first_row, std::size_t count,
                                              const float* heights)>& use) {
  const std::size_t block_rows = std::max<std::size_t>(1, (std::size_t{1} << 22) / cols);
  std::vector<float> block(std::min(block_rows, rows) * cols);
  for (std::size_t top = 0; top < rows; top += block_rows) {
    const std::size_t count = std::min(block_rows, rows - top);
    read({top, 0, count, cols}, block.data());
    use(top, count, block.data());
  }
}

double dem_lowest_height(std::size_t rows, std::size_t cols, const WindowReader& read) {
  LowestHeight lowest;
  read_row_blocks(rows, cols, read,
                  [&lowest, cols](std::size_t, std::size_t count, const float* z) {
                    lowest.add(z, count * cols);
                  });
  return lowest.value();
}

double lowest_height_of_rows(std::size_t first_row, std::size_t rows, std::size_t cols,
                             const WindowReader& read) {
  LowestHeight lowest;
  const WindowReader part = [&read, first_row](const DemWindow& w, float* z) {
    read({w.row0 + first_row, w.col0, w.rows, w.cols}, z);
  };
  read_row_blocks(rows, cols, part,
                  [&lowest, cols](std::size_t, std::size_t count, const float* z) {
                    lowest.add(z, count * cols);
                  });
  return lowest.lowest_or_infinity();
}

StripLoader::StripLoader(const OrientedFrame& frame, WindowReader read, unsigned threads)
    : frame_(frame), read_(std::move(read)), threads_(threads) {}

void StripLoader::load(std::size_t first, std::size_t count, HeightGrid& strip) {
  if (frame_.resampled) {
    band_.load(frame_, first, count, read_);
    resample_profiles(band_, frame_, first, count, strip, threads_);
    return;
  }
  const DemWindow w = profile_window(frame_, first, count);
  // Seen from the west the window is the strip as it is; any other cardinal view turns it.
  const bool turned = frame_.row_per_p <= 0 || frame_.col_per_i <= 0;
  HeightGrid& target = turned ? window_ : strip;
  target.reshape(w.rows, w.cols, kUnset);
  read_(w, target.data());
  if (turned) orient_window(frame_, window_, strip);
}

OrientedGridBuilder::OrientedGridBuilder(const OrientedFrame& frame)
    : frame_(frame),
      grid_(frame.resampled ? HeightGrid(frame.dem_rows, frame.dem_cols, kUnset)
                            : HeightGrid(frame.profiles, frame.length, kUnset)) {}

void OrientedGridBuilder::add_rows(std::size_t first_row, std::size_t count, const float* rows) {
  if (!frame_.resampled) {
    scatter_dem_rows(frame_, first_row, count, rows, frame_.dem_cols, grid_);
  } else {
    if (first_row + count > frame_.dem_rows) throw Error("DEM block does not match the frame");
    std::copy(rows, rows + count * frame_.dem_cols, grid_.row(first_row));
  }
  lowest_.add(rows, count * frame_.dem_cols);
}

HeightGrid OrientedGridBuilder::finish(unsigned threads) {
  if (!frame_.resampled) return std::move(grid_);
  return orient(grid_, frame_, threads);
}

double OrientedGridBuilder::dem_lowest_height() const {
  return lowest_.value();
}

TurnedDem turn_dem(const OrientedFrame& frame, const WindowReader& read,
                   const std::function<void(double)>& rows_read) {
  OrientedGridBuilder builder(frame);
  read_row_blocks(
      frame.dem_rows, frame.dem_cols, read,
      [&](std::size_t first_row, std::size_t count, const float* heights) {
        builder.add_rows(first_row, count, heights);
        if (rows_read) {
          rows_read(static_cast<double>(first_row + count) / static_cast<double>(frame.dem_rows));
        }
      });
  TurnedDem turned;
  turned.lowest_height = builder.dem_lowest_height();
  turned.oriented = builder.finish();
  return turned;
}

}  // namespace tsk
