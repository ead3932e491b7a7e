// Stage 2 (SPEC 1.2): transformed heights, hidden cells, occluding cells and their hidden zones.
#pragma once

#include <cstddef>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/params.h"

namespace tsk {

// t = ve * z + B * d * i, the height of cell i in the tilted, exaggerated model.
inline double transformed_height(float z, std::size_t i, double d, const ViewParams& view) {
  return view.ve * static_cast<double>(z) + view.base_slope() * d * static_cast<double>(i);
}

// Sets valid, hidden and occluding on cells [first, length) of one profile; `flags` must be
// cleared and the cells before `first` must be nodata.
void classify_profile_visibility(const float* z, std::uint8_t* flags, std::size_t length, double d,
                                 const ViewParams& view, std::size_t first = 0);

// All profiles; `flags` is resized to the grid and cleared first.
void classify_visibility(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                         unsigned threads = 0, const ProgressFn& progress = {});

// The hidden zone behind an occluding cell.
struct HiddenZone {
  std::size_t occluder = 0;
  std::size_t last = 0;          // last hidden cell of the zone (nodata inside the zone skipped)
  std::size_t hidden_cells = 0;  // number of hidden cells in the zone
  double depth_m = 0.0;          // max(t[occluder] - t[j]) over the zone, divided by ve
};

// Walks the zone that follows occluding cell i of a classified profile.
HiddenZone hidden_zone(const float* z, const std::uint8_t* flags, std::size_t length, std::size_t i,
                       double d, const ViewParams& view);

}  // namespace tsk
