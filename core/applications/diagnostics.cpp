#include "core/applications/diagnostics.h"

#include <cmath>

#include "core/method/slope_filter.h"

namespace tsk {
namespace {

// Calls value(p, i) for the oriented cell behind each DEM cell and stores it in a DEM grid.
template <typename T, typename F>
Grid<T> to_dem_grid(const OrientedFrame& frame, T outside, F value) {
  Grid<T> out(frame.dem_rows, frame.dem_cols, outside);
  if (!frame.resampled) {
    for (std::size_t p = 0; p < frame.profiles; ++p)
      for (std::size_t i = 0; i < frame.length; ++i)
        out(frame.dem_row(p, i), frame.dem_col(p, i)) = value(p, i);
    return out;
  }
  for (std::size_t r = 0; r < frame.dem_rows; ++r) {
    for (std::size_t col = 0; col < frame.dem_cols; ++col) {
      double p = 0, s = 0;
      frame.from_pixel({static_cast<double>(col) + 0.5, static_cast<double>(r) + 0.5}, p, s);
      p = std::round(p), s = std::round(s);
      if (p < 0 || s < 0 || p >= static_cast<double>(frame.profiles) ||
          s >= static_cast<double>(frame.length)) {
        continue;
      }
      out(r, col) = value(static_cast<std::size_t>(p), static_cast<std::size_t>(s));
    }
  }
  return out;
}

}  // namespace

const char* cell_class_name(CellClass c) {
  static const char* const names[kCellClassCount] = {"nodata", "visible", "hidden", "occluding",
                                                     "c-set",  "f-set",   "t-set"};
  return names[static_cast<int>(c)];
}

CellClass cell_class(std::uint8_t f) {
  if (!(f & cell::valid)) return CellClass::nodata;
  if (f & cell::thinned) return CellClass::thinned;
  if (f & cell::filtered) return CellClass::filtered;
  if (f & cell::occluding) return CellClass::occluding;
  if (f & cell::candidate) return CellClass::candidate;
  if (f & cell::hidden) return CellClass::hidden;
  return CellClass::visible;
}

Grid<std::uint8_t> classification_map(const CellFlags& flags, const OrientedFrame& frame) {
  return to_dem_grid<std::uint8_t>(frame, 0, [&](std::size_t p, std::size_t i) {
    return static_cast<std::uint8_t>(cell_class(flags(p, i)));
  });
}

HeightGrid row_slope_map(const HeightGrid& oriented, const OrientedFrame& frame) {
  return to_dem_grid<float>(frame, kNoData, [&](std::size_t p, std::size_t i) {
    return static_cast<float>(std::fabs(row_slope(oriented, p, i, frame.w)) * 100.0);
  });
}

}  // namespace tsk
