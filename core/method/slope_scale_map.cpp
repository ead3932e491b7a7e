#include "core/method/slope_scale_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/method/slope_survey.h"

namespace tsk {

SlopeScaleMap::SlopeScaleMap(std::size_t block_rows, std::size_t block_cols, std::size_t window,
                             std::vector<float> scales)
    : block_rows_(block_rows),
      block_cols_(block_cols),
      window_(static_cast<double>(window)),
      scales_(std::move(scales)) {
  if (!scales_.empty()) {
    const auto [lo, hi] = std::minmax_element(scales_.begin(), scales_.end());
    lowest_ = *lo, highest_ = *hi;
  }
}

float SlopeScaleMap::scale_at(PixelPoint px) const {
  // Continuous block coordinates with block centres at integers, held inside the lattice.
  const double u = std::clamp(px.col / window_ - 0.5, 0.0, static_cast<double>(block_cols_ - 1));
  const double v = std::clamp(px.row / window_ - 0.5, 0.0, static_cast<double>(block_rows_ - 1));
  const std::size_t c0 = static_cast<std::size_t>(u), r0 = static_cast<std::size_t>(v);
  const std::size_t c1 = std::min(c0 + 1, block_cols_ - 1), r1 = std::min(r0 + 1, block_rows_ - 1);
  const double fu = u - static_cast<double>(c0), fv = v - static_cast<double>(r0);
  const double top = block(r0, c0) + fu * (block(r0, c1) - block(r0, c0));
  const double bottom = block(r1, c0) + fu * (block(r1, c1) - block(r1, c0));
  return static_cast<float>(top + fv * (bottom - top));
}

namespace {

// Slopes of one band of blocks, counted block by block and turned into scales when it is done.
class BandOfBlocks {
 public:
  BandOfBlocks(std::size_t block_cols, std::size_t window,
               const std::function<double(double)>& scale_of, double fallback)
      : histograms_(block_cols), window_(window), scale_of_(scale_of), fallback_(fallback) {}

  void add(std::size_t col, float slope_pct) { histograms_[col / window_].add(slope_pct); }

  // Appends the band's scales to `scales` and starts a new band.
  void finish(std::vector<float>& scales) {
    // A block needs slopes on a tenth of its cells to tell its own steepness.
    const std::uint64_t enough = std::max<std::uint64_t>(1, window_ * window_ / 10);
    for (SlopeHistogram& h : histograms_) {
      const double scale = h.total() >= enough ? scale_of_(h.quantile(0.5)) : fallback_;
      scales.push_back(static_cast<float>(scale));
      h = SlopeHistogram();
    }
  }

 private:
  std::vector<SlopeHistogram> histograms_;
  std::size_t window_;
  const std::function<double(double)>& scale_of_;
  double fallback_;
};

}  // namespace

SlopeScaleMap map_slope_scales(std::size_t rows, std::size_t cols, double dx, double dy,
                               std::size_t window, double height_tolerance,
                               const std::function<double(double)>& scale_of, double fallback,
                               const WindowReader& read) {
  const std::size_t block_rows = (rows + window - 1) / window;
  const std::size_t block_cols = (cols + window - 1) / window;
  std::vector<float> scales;
  scales.reserve(block_rows * block_cols);
  BandOfBlocks band(block_cols, window, scale_of, fallback);
  // A row's slopes need the row below it: two rows side by side, the upper one measured.
  std::vector<float> pair(2 * cols);
  std::size_t measured = 0;  // the next row to measure
  auto measure = [&](std::size_t row) {
    for (std::size_t c = 0; c + 1 < cols; ++c) {
      const float slope = cell_slope_pct(pair.data(), cols, c, dx, dy, height_tolerance);
      if (slope >= 0) band.add(c, slope);
    }
    if ((row + 1) % window == 0) band.finish(scales);
  };
  read_row_blocks(rows, cols, read, [&](std::size_t first, std::size_t count, const float* z) {
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t row = first + k;
      std::memcpy(pair.data() + cols, z + k * cols, cols * sizeof(float));
      if (row > 0) measure(measured++);
      std::memcpy(pair.data(), pair.data() + cols, cols * sizeof(float));
    }
  });
  // The last row has no row below to measure its slopes with, but its band is finished.
  if (scales.size() < block_rows * block_cols) band.finish(scales);
  return SlopeScaleMap(block_rows, block_cols, window, std::move(scales));
}

}  // namespace tsk
