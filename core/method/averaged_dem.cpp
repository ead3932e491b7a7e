#include "core/method/averaged_dem.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/drawn/drawing_scale.h"

namespace tsk {
namespace {

// Row `row` of the averaged DEM, columns [col0, col0 + cols), into `out`: one read of the
// source's block row, summed column by column.
void average_row(const DemSource& dem, std::size_t factor, std::size_t row, std::size_t col0,
                 std::size_t cols, std::vector<float>& block, std::vector<double>& sum,
                 std::vector<std::size_t>& count, float* out) {
  const std::size_t top = row * factor, left = col0 * factor;
  const std::size_t rows_in = std::min(factor, dem.grid.rows - top);
  const std::size_t cols_in = std::min(cols * factor, dem.grid.cols - left);
  block.resize(rows_in * cols_in);
  dem.read({top, left, rows_in, cols_in}, block.data());
  sum.assign(cols, 0.0);
  count.assign(cols, 0);
  for (std::size_t r = 0; r < rows_in; ++r) {
    const float* z = block.data() + r * cols_in;
    for (std::size_t c = 0; c < cols_in; ++c) {
      if (!std::isfinite(z[c])) continue;
      sum[c / factor] += static_cast<double>(z[c]);
      ++count[c / factor];
    }
  }
  for (std::size_t c = 0; c < cols; ++c)
    out[c] = count[c] ? static_cast<float>(sum[c] / static_cast<double>(count[c])) : kNoData;
}

}  // namespace

DemGrid averaged_grid(const DemGrid& grid, std::size_t factor) {
  if (factor == 0) throw Error("a DEM cannot be averaged by a factor of 0");
  const auto k = static_cast<double>(factor);
  return {(grid.rows + factor - 1) / factor, (grid.cols + factor - 1) / factor, grid.dx * k,
          grid.dy * k};
}

std::size_t run_averaging(const SilhouetteParams& params, const DemGrid& grid,
                          const GeoTransform& geotransform) {
  return params.strokes.drawn() ? scale_averaging(params.strokes.scale, grid, geotransform) : 1;
}

DemSource averaged_dem(const DemSource& dem, std::size_t factor) {
  if (factor == 1) return dem;
  DemSource coarse;
  coarse.grid = averaged_grid(dem.grid, factor);  // refuses a factor of 0
  coarse.geotransform = dem.geotransform;
  for (const int i : {1, 2, 4, 5})
    coarse.geotransform.a[static_cast<std::size_t>(i)] *= static_cast<double>(factor);
  const DemGrid grid = coarse.grid;
  coarse.read = [&dem, factor, grid](const DemWindow& w, float* heights) {
    if (w.row0 > grid.rows || w.rows > grid.rows - w.row0 || w.col0 > grid.cols ||
        w.cols > grid.cols - w.col0)
      throw Error("the window of " + std::to_string(w.rows) + " x " + std::to_string(w.cols) +
                  " cells at row " + std::to_string(w.row0) + ", column " + std::to_string(w.col0) +
                  " does not lie in the averaged DEM's " + std::to_string(grid.rows) + " x " +
                  std::to_string(grid.cols));
    std::vector<float> block;
    std::vector<double> sum;
    std::vector<std::size_t> count;
    for (std::size_t r = 0; r < w.rows; ++r)
      average_row(dem, factor, w.row0 + r, w.col0, w.cols, block, sum, count, heights + r * w.cols);
  };
  return coarse;
}

}  // namespace tsk
