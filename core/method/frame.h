// How the oriented grid of SPEC 1.1 sits on the DEM: the frame of a view, its exact integer map
// for cardinal views and its affine pixel map for every view, both ways.
#pragma once

#include <cstddef>
#include <cstdint>

namespace tsk {

// A DEM pixel position: column and row, continuous, cell (r, c) has its centre at (c+0.5, r+0.5).
struct PixelPoint {
  double col;
  double row;
};

// A DEM's own grid: rows x cols cells, dx east-west and dy north-south in ground units, row 0
// north. What a view turns (make_frame); it knows no azimuth.
struct DemGrid {
  std::size_t rows = 0, cols = 0;
  double dx = 1.0, dy = 1.0;
};

// How oriented cells sit on the DEM. Cardinal views (0, 90, 180, 270) are exact flips: an integer
// map dem_row = row0 + row_per_p * p + row_per_i * i (likewise the column). Any other azimuth
// resamples the DEM onto a grid aligned with the line of sight (spacing min(dx, dy), bilinear).
// Both kinds keep the exact affine map to_pixel() from oriented positions to DEM pixels.
struct OrientedFrame {
  std::size_t profiles = 0;  // P
  std::size_t length = 0;    // L, cells per profile
  double d = 1.0;            // spacing along profiles, ground units
  double w = 1.0;            // spacing across profiles, ground units
  double azimuth_deg = 90;   // normalised to [0, 360)
  bool resampled = false;    // false: cardinal view, exact flip of the DEM
  std::size_t dem_rows = 0, dem_cols = 0;
  double dem_dx = 1.0, dem_dy = 1.0;  // the DEM's own cell sizes, ground units

  // Exact integer map, cardinal views only.
  std::int64_t row0 = 0, row_per_p = 0, row_per_i = 0;
  std::int64_t col0 = 0, col_per_p = 0, col_per_i = 0;

  // Affine map of oriented positions to DEM pixels, every view.
  double px_col0 = 0, px_col_per_p = 0, px_col_per_i = 0;
  double px_row0 = 0, px_row_per_p = 0, px_row_per_i = 0;

  // The DEM's own grid, which the frame turns.
  DemGrid dem_grid() const { return {dem_rows, dem_cols, dem_dx, dem_dy}; }

  // True when the oriented grid is the DEM as it lies (the view from the west): profile p is DEM
  // row p and cell i its column i, no turn, no flip.
  bool as_it_lies() const {
    return !resampled && row_per_p == 1 && col_per_i == 1 && row0 == 0 && col0 == 0;
  }

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
    return {px_col0 + px_col_per_p * p + px_col_per_i * s,
            px_row0 + px_row_per_p * p + px_row_per_i * s};
  }
  // The continuous oriented position (profile p, position s along it) at DEM pixel position px:
  // to_pixel inverted.
  void from_pixel(PixelPoint px, double& p, double& s) const {
    const double u = px.col - px_col0, v = px.row - px_row0;
    const double det = px_col_per_p * px_row_per_i - px_col_per_i * px_row_per_p;
    p = (px_row_per_i * u - px_col_per_i * v) / det;
    s = (px_col_per_p * v - px_row_per_p * u) / det;
  }
};

// True for the views that are exact flips of the DEM: azimuth 0, 90, 180 or 270 (modulo 360).
bool is_cardinal(double azimuth_deg);

// The frame for a DEM of rows x cols with cell sizes dx (east-west) and dy (north-south), row 0
// north, seen facing `azimuth_deg`. Exact for cardinal views, resampled otherwise. Throws Error
// for an empty grid, bad cell sizes or an oriented grid too large to address.
OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg);

// The frame of `grid` seen facing `azimuth_deg`: make_frame above.
OrientedFrame make_frame(const DemGrid& grid, double azimuth_deg);

// The resampled frame even at a cardinal azimuth (to compare the two paths).
OrientedFrame make_resampled_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                                   double azimuth_deg);

}  // namespace tsk
