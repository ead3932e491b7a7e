#include "core/method/orient.h"

#include "core/base/errors.h"
#include "core/method/resample.h"

namespace tsk {

void scatter_dem_rows(const OrientedFrame& frame, std::size_t first_row, std::size_t count,
                      const float* rows, std::size_t cols, HeightGrid& oriented) {
  if (frame.resampled) throw Error("a resampled view needs the whole DEM (use orient)");
  const bool profiles_are_rows = frame.row_per_p != 0;
  if (cols != frame.dem_cols || first_row + count > frame.dem_rows ||
      oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("DEM block does not match the oriented frame");
  }
  if (profiles_are_rows) {
    for (std::size_t k = 0; k < count; ++k) {
      // The row is one profile, possibly reversed.
      const float* src = rows + k * cols;
      const auto p = static_cast<std::size_t>(
          (static_cast<std::int64_t>(first_row + k) - frame.row0) * frame.row_per_p);
      float* dst = oriented.row(p);
      if (frame.col_per_i > 0) {
        std::copy(src, src + cols, dst);
      } else {
        std::reverse_copy(src, src + cols, dst);
      }
    }
    return;
  }
  // Each row is cell i of every profile: a transpose. It goes a tile of columns at a time down
  // all the rows, so that the tile's profiles stay in cache from row to row; row by row, a DEM
  // far wider than high would write every profile's cache line again for each row.
  constexpr std::size_t kTile = 256;
  for (std::size_t c0 = 0; c0 < cols; c0 += kTile) {
    const std::size_t c1 = std::min(cols, c0 + kTile);
    for (std::size_t k = 0; k < count; ++k) {
      const float* src = rows + k * cols;
      const auto i = static_cast<std::size_t>(
          (static_cast<std::int64_t>(first_row + k) - frame.row0) * frame.row_per_i);
      for (std::size_t c = c0; c < c1; ++c) {
        const auto p =
            static_cast<std::size_t>((static_cast<std::int64_t>(c) - frame.col0) * frame.col_per_p);
        oriented(p, i) = src[c];
      }
    }
  }
}

DemWindow profile_window(const OrientedFrame& frame, std::size_t first, std::size_t count) {
  if (frame.resampled) throw Error("strips work for the cardinal views (azimuth 0, 90, 180, 270)");
  if (count == 0 || first + count > frame.profiles) throw Error("strip outside the grid");
  const bool by_rows = frame.row_per_p != 0;  // views from the west or east: profiles are rows
  const bool reversed = by_rows ? frame.row_per_p < 0 : frame.col_per_p < 0;
  const std::size_t extent = by_rows ? frame.dem_rows : frame.dem_cols;
  const std::size_t start = reversed ? extent - (first + count) : first;
  DemWindow w;
  w.row0 = by_rows ? start : 0;
  w.col0 = by_rows ? 0 : start;
  w.rows = by_rows ? count : frame.dem_rows;
  w.cols = by_rows ? frame.dem_cols : count;
  return w;
}

void orient_window(const OrientedFrame& frame, const HeightGrid& window, HeightGrid& out) {
  // The window seen from the same side is exactly its run of profiles, in order.
  const OrientedFrame turned = make_frame(window.rows(), window.cols(), 1, 1, frame.azimuth_deg);
  out.reshape(turned.profiles, turned.length, kUnset);
  scatter_dem_rows(turned, 0, window.rows(), window.data(), window.cols(), out);
}

HeightGrid orient(const HeightGrid& dem, const OrientedFrame& frame, unsigned threads) {
  if (dem.rows() != frame.dem_rows || dem.cols() != frame.dem_cols) {
    throw Error("the DEM does not match the oriented frame");
  }
  HeightGrid oriented(frame.profiles, frame.length, kUnset);
  if (!frame.resampled) {
    scatter_dem_rows(frame, 0, dem.rows(), dem.data(), dem.cols(), oriented);
    return oriented;
  }
  resample_profiles(dem, frame, 0, frame.profiles, oriented, threads);
  return oriented;
}

}  // namespace tsk
