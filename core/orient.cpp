#include "orient.h"

#include <cmath>
#include <string>

namespace tsk {

OrientedFrame make_frame(std::size_t rows, std::size_t cols, double dx, double dy,
                         double azimuth_deg) {
  if (rows == 0 || cols == 0) throw Error("the DEM has no cells");
  checked_cell_count(rows, cols);
  if (!std::isfinite(dx) || !std::isfinite(dy) || dx <= 0.0 || dy <= 0.0) {
    throw Error("cell sizes must be finite and positive, got " + std::to_string(dx) + " x " +
                std::to_string(dy));
  }
  double normalised = std::fmod(azimuth_deg, 360.0);
  if (normalised < 0) normalised += 360.0;
  const int azimuth = static_cast<int>(std::lround(normalised)) % 360;
  if (std::fabs(normalised - std::round(normalised)) > 1e-9 || azimuth % 90 != 0) {
    throw Error("azimuth " + std::to_string(azimuth_deg) +
                " is not a cardinal view; use 0, 90, 180 or 270");
  }
  const auto last_row = static_cast<std::int64_t>(rows) - 1;
  const auto last_col = static_cast<std::int64_t>(cols) - 1;
  OrientedFrame f;
  f.azimuth_deg = azimuth;
  switch (azimuth) {
    case 90:  // viewed from the west: profile = row (north first), cell = column (west first)
      f.profiles = rows, f.length = cols, f.d = dx, f.w = dy;
      f.row_per_p = 1, f.col_per_i = 1;
      break;
    case 270:  // viewed from the east: profile = row (south first), cell = column (east first)
      f.profiles = rows, f.length = cols, f.d = dx, f.w = dy;
      f.row0 = last_row, f.row_per_p = -1, f.col0 = last_col, f.col_per_i = -1;
      break;
    case 0:  // viewed from the south: profile = column (west first), cell = row (south first)
      f.profiles = cols, f.length = rows, f.d = dy, f.w = dx;
      f.row0 = last_row, f.row_per_i = -1, f.col_per_p = 1;
      break;
    default:  // 180, viewed from the north: profile = column (east first), cell = row (north first)
      f.profiles = cols, f.length = rows, f.d = dy, f.w = dx;
      f.row_per_i = 1, f.col0 = last_col, f.col_per_p = -1;
      break;
  }
  return f;
}

void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented) {
  const bool profiles_are_rows = frame.row_per_p != 0;
  const std::size_t dem_rows = profiles_are_rows ? frame.profiles : frame.length;
  if (cols != (profiles_are_rows ? frame.length : frame.profiles) || first_row + count > dem_rows ||
      oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("DEM block does not match the oriented frame");
  }
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t r = first_row + k;
    const float* src = rows + k * cols;
    if (profiles_are_rows) {
      // The row is one profile, possibly reversed.
      const auto p =
          static_cast<std::size_t>((static_cast<std::int64_t>(r) - frame.row0) * frame.row_per_p);
      float* dst = oriented.row(p);
      if (frame.col_per_i > 0) {
        for (std::size_t c = 0; c < cols; ++c) dst[c] = src[c];
      } else {
        for (std::size_t c = 0; c < cols; ++c) dst[cols - 1 - c] = src[c];
      }
    } else {
      // The row is cell i of every profile.
      const auto i =
          static_cast<std::size_t>((static_cast<std::int64_t>(r) - frame.row0) * frame.row_per_i);
      for (std::size_t c = 0; c < cols; ++c) {
        const auto p =
            static_cast<std::size_t>((static_cast<std::int64_t>(c) - frame.col0) * frame.col_per_p);
        oriented(p, i) = src[c];
      }
    }
  }
}

HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame) {
  HeightGrid oriented(frame.profiles, frame.length);
  scatter_dem_rows(frame, 0, dem.rows(), dem.data(), dem.cols(), oriented);
  return oriented;
}

}  // namespace tsk
