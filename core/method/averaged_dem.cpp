#include "core/method/averaged_dem.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "core/base/parallel.h"
#include "core/drawn/drawing_scale.h"
#include "core/method/dem_windows.h"

namespace tsk {
namespace {

// Row `row` of the averaged DEM, columns [col0, col0 + cols), into `out`: one read of the
// source's block row, summed block by block of `factor` columns (each sum over its rows, then its
// columns, in order).
void average_row(const WindowReader& read, const DemGrid& fine, std::size_t factor, std::size_t row,
                 std::size_t col0, std::size_t cols, std::vector<float>& block,
                 std::vector<double>& sum, std::vector<std::size_t>& count, float* out) {
  const std::size_t top = row * factor, left = col0 * factor;
  const std::size_t rows_in = std::min(factor, fine.rows - top);
  const std::size_t cols_in = std::min(cols * factor, fine.cols - left);
  block.resize(rows_in * cols_in);
  read({top, left, rows_in, cols_in}, block.data());
  sum.assign(cols, 0.0);
  count.assign(cols, 0);
  for (std::size_t r = 0; r < rows_in; ++r) {
    const float* z = block.data() + r * cols_in;
    for (std::size_t c = 0, first = 0; c < cols; ++c, first += factor) {
      const std::size_t last = std::min(first + factor, cols_in);
      for (std::size_t k = first; k < last; ++k) {
        if (!std::isfinite(z[k])) continue;
        sum[c] += static_cast<double>(z[k]);
        ++count[c];
      }
    }
  }
  for (std::size_t c = 0; c < cols; ++c)
    out[c] = count[c] ? static_cast<float>(sum[c] / static_cast<double>(count[c])) : kNoData;
}

// Rows [first, end) of the averaged DEM, whole, into `grid`; `done(rows)` after each row.
void average_rows(const WindowReader& read, const DemGrid& fine, std::size_t factor,
                  std::size_t first, std::size_t end, HeightGrid& grid,
                  const std::function<void(std::size_t)>& done) {
  std::vector<float> block;
  std::vector<double> sum;
  std::vector<std::size_t> count;
  for (std::size_t row = first; row < end; ++row) {
    average_row(read, fine, factor, row, 0, grid.cols(), block, sum, count, grid.row(row));
    done(row + 1 - first);
  }
}

}  // namespace

DemGrid averaged_grid(const DemGrid& grid, std::size_t factor) {
  if (factor == 0) throw Error("a DEM cannot be averaged by a factor of 0");
  const auto k = static_cast<double>(factor);
  return {(grid.rows + factor - 1) / factor, (grid.cols + factor - 1) / factor, grid.dx * k,
          grid.dy * k};
}

GeoTransform averaged_geotransform(const GeoTransform& geotransform, std::size_t factor) {
  GeoTransform coarse = geotransform;
  for (const int i : {1, 2, 4, 5})
    coarse.a[static_cast<std::size_t>(i)] *= static_cast<double>(factor);
  return coarse;
}

std::size_t run_averaging(const SilhouetteParams& params, const DemGrid& grid,
                          const GeoTransform& geotransform) {
  return params.strokes.drawn() ? scale_averaging(params.strokes.scale, grid, geotransform) : 1;
}

DemSource averaged_dem(const DemSource& dem, std::size_t factor) {
  if (factor == 1) return dem;
  DemSource coarse;
  coarse.grid = averaged_grid(dem.grid, factor);  // refuses a factor of 0
  coarse.geotransform = averaged_geotransform(dem.geotransform, factor);
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
      average_row(dem.read, dem.grid, factor, w.row0 + r, w.col0, w.cols, block, sum, count,
                  heights + r * w.cols);
  };
  return coarse;
}

HeightGrid read_averaged(const DemSource& dem, std::size_t factor, const ProgressFn& progress) {
  const DemGrid grid = averaged_grid(dem.grid, factor);
  HeightGrid heights(grid.rows, grid.cols, kUnset);
  // The northern half through `read` on this thread (which tells the progress), the southern
  // half through `read_alongside` on another: each half's fine rows, and so the file's blocks,
  // read once (but the block row the halves share).
  const bool two = dem.read_alongside && grid.rows > 1;
  const std::size_t half = two ? grid.rows / 2 : grid.rows;
  run_two_shares(two, [&](int share, const std::atomic<bool>& stop) {
    const auto stop_when_asked = [&stop](std::size_t) {
      if (stop) throw Cancelled();
    };
    if (share == 1) {
      average_rows(dem.read_alongside, dem.grid, factor, half, grid.rows, heights, stop_when_asked);
      return;
    }
    average_rows(dem.read, dem.grid, factor, 0, half, heights, [&](std::size_t rows) {
      stop_when_asked(rows);
      tell_progress(progress, static_cast<double>(rows) / static_cast<double>(half));
    });
  });
  return heights;
}

DemSource held_source(std::shared_ptr<const HeightGrid> heights, const DemGrid& grid,
                      const GeoTransform& geotransform) {
  if (!heights || heights->rows() != grid.rows || heights->cols() != grid.cols)
    throw Error("internal: the heights held do not match the DEM's grid");
  DemSource held{grid, geotransform, {}, {}};
  held.read = [heights](const DemWindow& w, float* out) { copy_window(*heights, w, out); };
  // Memory read alike from any thread.
  held.read_alongside = held.read;
  return held;
}

}  // namespace tsk
