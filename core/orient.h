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

  // Exact integer map, cardinal views only.
  std::int64_t row0 = 0, row_per_p = 0, row_per_i = 0;
  std::int64_t col0 = 0, col_per_p = 0, col_per_i = 0;

  // Affine map of oriented positions to DEM pixels, every view.
  double px_col0 = 0, px_col_per_p = 0, px_col_per_i = 0;
  double px_row0 = 0, px_row_per_p = 0, px_row_per_i = 0;

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
};

// True for the views that are exact flips of the DEM: azimuth 0, 90, 180 or 270 (modulo 360).
bool is_cardinal(double azimuth_deg);

// The frame for a DEM of rows x cols with cell sizes dx (east-west) and dy (north-south), row 0
// north, seen facing `azimuth_deg`. Exact for cardinal views, resampled otherwise. Throws Error
// for an empty grid, bad cell sizes or an oriented grid too large to address.
OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg);

// The resampled frame even at a cardinal azimuth (to compare the two paths).
OrientedFrame make_resampled_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                                   double azimuth_deg);

// Copies DEM rows [first_row, first_row + count) into their places in the oriented grid, so an
// adapter can read a raster block by block without holding the DEM twice. Cardinal frames only.
void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented);

// The whole DEM turned (cardinal) or resampled (any other azimuth: bilinear, nodata where a
// source cell with weight is nodata or outside the DEM).
HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame, unsigned threads = 0);

// Resamples profiles [first, first + count) of a resampled frame into `out` (rows = profiles),
// reusing its memory when it already has that shape: for streaming a view strip by strip.
void resample_profiles(const HeightGrid& dem, const OrientedFrame& frame, std::size_t first,
                       std::size_t count, HeightGrid& out, unsigned threads = 0);

// Builds the oriented grid from DEM rows delivered block by block, top to bottom, as raster
// adapters read them: scattered straight into place for cardinal views, gathered into the whole
// DEM and resampled at the end for other azimuths.
class OrientedGridBuilder {
 public:
  explicit OrientedGridBuilder(const OrientedFrame& frame);
  void add_rows(std::size_t first_row, std::size_t count, const float* rows);
  HeightGrid finish(unsigned threads = 0);
  // Resampled frames: the DEM as delivered, for a caller that resamples it strip by strip.
  HeightGrid take_dem();

 private:
  const OrientedFrame& frame_;
  HeightGrid grid_;  // the oriented grid (cardinal) or the DEM (resampled)
};

// The DEM window (rows or columns, by view) that holds oriented profiles [first, first + count)
// of a cardinal frame, for readers that load a DEM strip by strip.
struct DemWindow {
  std::size_t row0 = 0, col0 = 0, rows = 0, cols = 0;
};
DemWindow profile_window(const OrientedFrame& frame, std::size_t first, std::size_t count);

// Profiles [first, first + count) turned from their window (read as rows x cols, row 0 north).
HeightGrid orient_window(const OrientedFrame& frame, const HeightGrid& window);

// Bilinear height at a DEM pixel position; NaN outside the cell centres' hull or next to nodata.
float sample_bilinear(const HeightGrid& dem, PixelPoint px);

}  // namespace tsk
