// The one grid type of the core: row-major, (row, col) indexing, NaN as the only nodata.
#pragma once

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/base/errors.h"
#include "core/base/large_pages.h"
#include "core/base/release_storage.h"

namespace tsk {

// Largest grid the core accepts: each side must fit an int32 (profile and cell indices are
// stored as int32) and the cell count must be addressable.
constexpr std::size_t kMaxGridSide =
    static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());

// rows * cols, refusing sizes that overflow or exceed the core's index range.
inline std::size_t checked_cell_count(std::size_t rows, std::size_t cols) {
  if (rows > kMaxGridSide || cols > kMaxGridSide) {
    throw Error("grid of " + std::to_string(rows) + " x " + std::to_string(cols) +
                " cells is too large: each side must be below 2^31");
  }
  if (cols != 0 && rows > std::numeric_limits<std::size_t>::max() / cols) {
    throw Error("grid cell count overflows");
  }
  return rows * cols;
}

// Tag for a grid whose cells are left unset because every one of them is written next.
struct Unset {};
constexpr Unset kUnset{};

template <typename T>
class Grid {
 public:
  Grid() = default;
  Grid(std::size_t rows, std::size_t cols, T fill = T{})
      : rows_(rows), cols_(cols), cells_(checked_cell_count(rows, cols), fill) {}
  Grid(std::size_t rows, std::size_t cols, Unset)
      : rows_(rows), cols_(cols), cells_(checked_cell_count(rows, cols)) {}

  // Makes this a rows x cols grid of unset cells, in the memory it has when that is large enough
  // (nothing changes for the shape it has): for buffers refilled strip after strip, as fresh
  // memory costs a page fault for every page.
  void reshape(std::size_t rows, std::size_t cols, Unset) {
    const std::size_t n = checked_cell_count(rows, cols);
    if (n > cells_.capacity()) release_storage(cells_);  // no cell is worth copying or keeping
    cells_.resize(n);
    rows_ = rows;
    cols_ = cols;
  }

  std::size_t rows() const { return rows_; }
  std::size_t cols() const { return cols_; }
  std::size_t size() const { return cells_.size(); }
  bool empty() const { return cells_.empty(); }

  T& operator()(std::size_t r, std::size_t c) {
    assert(r < rows_ && c < cols_);
    return cells_[r * cols_ + c];
  }
  const T& operator()(std::size_t r, std::size_t c) const {
    assert(r < rows_ && c < cols_);
    return cells_[r * cols_ + c];
  }
  T* row(std::size_t r) {
    assert(r < rows_);
    return cells_.data() + r * cols_;
  }
  const T* row(std::size_t r) const {
    assert(r < rows_);
    return cells_.data() + r * cols_;
  }
  T* data() { return cells_.data(); }
  const T* data() const { return cells_.data(); }

 private:
  std::size_t rows_ = 0;
  std::size_t cols_ = 0;
  std::vector<T, LargePageAllocator<T>> cells_;
};

using HeightGrid = Grid<float>;

constexpr float kNoData = std::numeric_limits<float>::quiet_NaN();

// Inside the core a height is data when it is finite; NaN and +-Inf are nodata.
inline bool is_data(float z) {
  return std::isfinite(z);
}

// Heights this far from 0 are float's fill values (3.4e38 and its negative, or 1e30), never
// terrain: a strip of them undeclared stood as a wall that hid everything behind it.
constexpr double kFillMagnitude = 1e30;

// Puts the core's NaN where a band's values hold no height: its nodata value, when it declares
// one, and float's fill values (what a reader does to every window before the core sees it).
inline void mark_nodata(float* values, std::size_t count, bool has_nodata, float nodata) {
  constexpr auto fill = static_cast<float>(kFillMagnitude);
  // Without a nodata value, a value that is not one: a comparison that never holds. Every value
  // is stored back, chosen without a branch, so that the loop runs in vector lanes.
  const float declared = has_nodata ? nodata : kNoData;
  for (std::size_t k = 0; k < count; ++k) {
    const float v = values[k];
    values[k] = v == declared || std::fabs(v) >= fill ? kNoData : v;
  }
}

// The lowest height with data among those added: the plan-oblique reference (SPEC 1.9), 0 when
// none had data.
class LowestHeight {
 public:
  void add(const float* z, std::size_t n) {
    std::size_t k = 0;
#if defined(__SSE2__)
    // Four at a time (a whole DEM passes through here as it is read): a lane with nodata, where
    // z - z is not 0, keeps its lowest.
    __m128 low = _mm_set1_ps(lowest_);
    for (; k + 4 <= n; k += 4) {
      const __m128 v = _mm_loadu_ps(z + k);
      const __m128 data = _mm_cmpeq_ps(_mm_sub_ps(v, v), _mm_setzero_ps());
      low = _mm_min_ps(low, _mm_or_ps(_mm_and_ps(data, v), _mm_andnot_ps(data, low)));
    }
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, low);
    for (float lane : lanes) lowest_ = std::min(lowest_, lane);
#endif
    for (; k < n; ++k)
      if (is_data(z[k])) lowest_ = std::min(lowest_, z[k]);
  }
  void add(const LowestHeight& other) {
    lowest_ = std::min(lowest_, other.lowest_);
  }
  double value() const {
    return std::isfinite(lowest_) ? static_cast<double>(lowest_) : 0.0;
  }
  // The lowest height added, +infinity when none had data: a part of a DEM's, which the least of
  // its parts' gives (value() of that, once the parts are in).
  double lowest_or_infinity() const {
    return static_cast<double>(lowest_);
  }

 private:
  float lowest_ = std::numeric_limits<float>::infinity();
};

}  // namespace tsk
