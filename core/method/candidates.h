// Stage 3 (SPEC 1.3, 1.4): column slopes and the candidate set (c-set).
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/params.h"

namespace tsk {

// True slope along the line of sight, forward difference, as a fraction; NaN at the last cell
// and next to nodata.
inline double column_slope(const float* z, std::size_t length, std::size_t i, double d) {
  if (i + 1 >= length || !is_data(z[i]) || !is_data(z[i + 1])) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return (static_cast<double>(z[i + 1]) - static_cast<double>(z[i])) / d;
}

// The c-set rule's bounds on the exaggerated column slope ve * gc: above `lower` and below
// `upper`. SPEC's are -B and 0. With a height tolerance (the adaptive filter) a step within it
// counts as flat, so each bound moves inwards by ve * tolerance / d; a tolerance of 0 leaves
// them exactly SPEC's.
struct CandidateBounds {
  double lower, upper;
  CandidateBounds(const ViewParams& view, double d, double height_tolerance = 0.0)
      : lower(-view.base_slope() + view.ve * height_tolerance / d),
        upper(-(view.ve * height_tolerance / d)) {}
};

// The c-set rule: back-facing (gc < 0) yet front-facing once exaggerated and tilted. Both
// comparisons are worked out (&, not &&), so that a loop over cells has no branch on the outcome.
inline bool is_candidate_slope(double gc, double ve, const CandidateBounds& bounds) {
  const double exaggerated = ve * gc;
  return (exaggerated < bounds.upper) & (exaggerated > bounds.lower);
}
inline bool is_candidate_slope(double gc, const ViewParams& view) {
  return is_candidate_slope(gc, view.ve, CandidateBounds(view, 1.0));
}

// Sets `candidate` on the cells of one profile that satisfy -B < ve * gc < 0, each bound moved
// inwards by a height tolerance (see CandidateBounds).
void select_profile_candidates(const float* z, std::uint8_t* flags, std::size_t length, double d,
                               const ViewParams& view, double height_tolerance = 0.0);

}  // namespace tsk
