// Local adaptivity of the slope filter: a scale for each neighbourhood of a DEM, so that a plain
// beside a mountain range is filtered by the plain's own slopes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "core/method/dem_windows.h"
#include "core/method/frame.h"

namespace tsk {

// Scales on a lattice of square blocks of DEM cells, read between the blocks' centres bilinearly
// so that the filter has no seams at their edges.
class SlopeScaleMap {
 public:
  // `scales` row by row, block_rows x block_cols of them, for blocks of `window` cells.
  SlopeScaleMap(std::size_t block_rows, std::size_t block_cols, std::size_t window,
                std::vector<float> scales);
  float scale_at(PixelPoint px) const;
  float lowest() const { return lowest_; }
  float highest() const { return highest_; }

 private:
  float block(std::size_t r, std::size_t c) const { return scales_[r * block_cols_ + c]; }

  std::size_t block_rows_, block_cols_;
  double window_;
  std::vector<float> scales_;
  float lowest_ = 1, highest_ = 1;
};

// The map of a DEM of rows x cols cells read through `read`, in blocks of `window` cells:
// scale_of(median slope of the block's cells that are not flat, percent) for each block, and
// `fallback` for blocks with too few such cells to tell. Reads the whole DEM once.
SlopeScaleMap map_slope_scales(std::size_t rows, std::size_t cols, double dx, double dy,
                               std::size_t window, double height_tolerance,
                               const std::function<double(double)>& scale_of, double fallback,
                               const WindowReader& read);

}  // namespace tsk
