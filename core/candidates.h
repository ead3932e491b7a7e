// Stage 3 (SPEC 1.3, 1.4): column slopes and the candidate set (c-set).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "flags.h"
#include "parallel.h"
#include "params.h"

namespace tsk {

// True slope along the line of sight, forward difference, as a fraction; NaN at the last cell
// and next to nodata.
inline double column_slope(const float* z, std::size_t length, std::size_t i, double d) {
  if (i + 1 >= length || !is_data(z[i]) || !is_data(z[i + 1])) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return (static_cast<double>(z[i + 1]) - static_cast<double>(z[i])) / d;
}

// The c-set rule: back-facing (gc < 0) yet front-facing once exaggerated and tilted. Both
// comparisons are worked out (&, not &&), so that a loop over cells has no branch on the outcome.
inline bool is_candidate_slope(double gc, const ViewParams& view) {
  const double exaggerated = view.ve * gc;
  return (exaggerated < 0.0) & (exaggerated > -view.base_slope());
}

// Sets `candidate` on the cells of one profile that satisfy -B < ve * gc < 0.
void select_profile_candidates(const float* z, std::uint8_t* flags, std::size_t length, double d,
                               const ViewParams& view);

}  // namespace tsk
