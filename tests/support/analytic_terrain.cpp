#include "analytic_terrain.h"

#include <algorithm>
#include <cmath>

namespace tsk {
namespace {

// Fills a grid from f(x, y) where x, y are offsets in cells from the grid centre, y north.
template <typename F>
HeightGrid fill_centred(std::size_t rows, std::size_t cols, F f) {
  HeightGrid g(rows, cols);
  const double cx = 0.5 * static_cast<double>(cols - 1);
  const double cy = 0.5 * static_cast<double>(rows - 1);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c) {
      g(r, c) = static_cast<float>(f(static_cast<double>(c) - cx, cy - static_cast<double>(r)));
    }
  }
  return g;
}

}  // namespace

HeightGrid make_plane(std::size_t rows, std::size_t cols, double cell, double slope_x,
                      double slope_y) {
  return fill_centred(rows, cols, [&](double x, double y) {
    return 1000.0 + slope_x * x * cell + slope_y * y * cell;
  });
}

HeightGrid make_step(std::size_t rows, std::size_t cols, double height, std::size_t step_col) {
  HeightGrid g(rows, cols);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < cols; ++c)
      g(r, c) = c >= step_col ? static_cast<float>(height) : 0.f;
  }
  return g;
}

HeightGrid make_bump(std::size_t rows, std::size_t cols, double height, double sigma_cells) {
  return fill_centred(rows, cols, [&](double x, double y) {
    return height * std::exp(-(x * x + y * y) / (2.0 * sigma_cells * sigma_cells));
  });
}

HeightGrid make_cone(std::size_t rows, std::size_t cols, double cell, double height, double slope) {
  return fill_centred(rows, cols, [&](double x, double y) {
    return std::max(0.0, height - slope * cell * std::hypot(x, y));
  });
}

HeightGrid make_ridge(std::size_t rows, std::size_t cols, double cell, double height,
                      double slope) {
  return fill_centred(rows, cols, [&](double x, double) {
    return std::max(0.0, height - slope * cell * std::fabs(x));
  });
}

}  // namespace tsk
