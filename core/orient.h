// Stage 1 (SPEC 1.1): turn the DEM into the oriented grid g[p][i] seen by the viewer.
// Profiles p run left to right as the viewer sees them, cells i front to back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "grid.h"

namespace tsk {

// A DEM pixel position: column and row, continuous, cell (r, c) has its centre at (c+0.5, r+0.5).
struct PixelPoint {
  double col;
  double row;
};

// The exact integer map between oriented cells and DEM cells for a cardinal view:
// dem_row = row0 + row_per_p * p + row_per_i * i, and likewise for the column.
struct OrientedFrame {
  std::size_t profiles = 0;  // P
  std::size_t length = 0;    // L, cells per profile
  double d = 1.0;            // spacing along profiles, ground units
  double w = 1.0;            // spacing across profiles, ground units
  int azimuth_deg = 90;      // 0, 90, 180 or 270

  std::int64_t row0 = 0, row_per_p = 0, row_per_i = 0;
  std::int64_t col0 = 0, col_per_p = 0, col_per_i = 0;

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
    return {static_cast<double>(col0) + col_per_p * p + col_per_i * s + 0.5,
            static_cast<double>(row0) + row_per_p * p + row_per_i * s + 0.5};
  }
};

// The frame for a DEM of rows x cols with cell sizes dx (east-west) and dy (north-south), row 0
// north. Throws Error for a non-cardinal azimuth, empty grid or bad cell sizes.
OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg);

// Copies DEM rows [first_row, first_row + count) into their places in the oriented grid, so an
// adapter can read a raster block by block without holding the DEM twice.
void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented);

// The whole DEM turned at once.
HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame);

}  // namespace tsk
