#include "core/method/visibility.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace tsk {

void classify_profile_visibility(const float* z, std::uint8_t* flags, std::size_t length, double d,
                                 const ViewParams& view, std::size_t first) {
  const double ve = view.ve;
  const double step = view.base_slope() * d;
  double running_max = -std::numeric_limits<double>::infinity();
  // The last valid visible cell, waiting to learn whether the next valid cell is hidden.
  std::size_t last_visible = length;
  for (std::size_t i = first; i < length; ++i) {
    if (!is_data(z[i])) continue;  // nodata: neither visible nor hidden; the maximum carries over
    const double t = ve * static_cast<double>(z[i]) + step * static_cast<double>(i);
    std::uint8_t f = cell::valid;
    if (t < running_max) {
      f |= cell::hidden;
      if (last_visible != length) flags[last_visible] |= cell::occluding;
    } else {
      running_max = t;
    }
    flags[i] = f;
    last_visible = (f & cell::hidden) ? length : i;
  }
}

void classify_visibility(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                         unsigned threads, const ProgressFn& progress) {
  flags.reshape(z.rows(), z.cols(), kUnset);
  const std::size_t length = z.cols();
  parallel_for(
      z.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          std::memset(flags.row(p), 0, length);
          classify_profile_visibility(z.row(p), flags.row(p), length, d, view);
        }
      },
      progress);
}

HiddenZone hidden_zone(const float* z, const std::uint8_t* flags, std::size_t length, std::size_t i,
                       double d, const ViewParams& view) {
  HiddenZone zone;
  zone.occluder = i;
  zone.last = i;
  const double t_occluder = transformed_height(z[i], i, d, view);
  double deepest = 0.0;
  for (std::size_t j = i + 1; j < length; ++j) {
    if (!(flags[j] & cell::valid)) continue;
    if (!(flags[j] & cell::hidden)) break;
    zone.last = j;
    ++zone.hidden_cells;
    deepest = std::max(deepest, t_occluder - transformed_height(z[j], j, d, view));
  }
  zone.depth_m = deepest / view.ve;
  return zone;
}

}  // namespace tsk
