// Analytic test terrains with known silhouettes, for the tests and the benchmark.
// All return rows x cols grids with row 0 north, heights in metres, cell size `cell` metres.
#pragma once

#include <cstddef>

#include "core/base/grid.h"

namespace tsk {

// z = slope_x * x + slope_y * y, x east, y north, slopes as fractions.
HeightGrid make_plane(std::size_t rows, std::size_t cols, double cell, double slope_x,
                      double slope_y);
// A cliff: low west of column `step_col`, `height` metres higher from it eastwards.
HeightGrid make_step(std::size_t rows, std::size_t cols, double height, std::size_t step_col);
// z = height * exp(-r^2 / (2 sigma^2)) around the grid centre, sigma in cells.
HeightGrid make_bump(std::size_t rows, std::size_t cols, double height, double sigma_cells);
// z = max(0, height - slope * r), r ground distance from the centre, slope as a fraction.
HeightGrid make_cone(std::size_t rows, std::size_t cols, double cell, double height, double slope);
// A north-south ridge through the centre column: z = max(0, height - slope * |x|).
HeightGrid make_ridge(std::size_t rows, std::size_t cols, double cell, double height, double slope);

}  // namespace tsk
