#include "core/method/candidates.h"

#include "core/base/vector_clones.h"

namespace tsk {

TSK_VECTOR_CLONES
void select_profile_candidates(const float* z, std::uint8_t* flags, std::size_t length, double d,
                               const ViewParams& view, double height_tolerance) {
  // is_candidate_slope(column_slope(...)) without column_slope's nodata checks, so that it
  // vectorises. They are not needed: with ve > 0 and d > 0, a NaN or infinite height at either
  // end gives a NaN or infinite slope, which fails one of the rule's comparisons. (A local copy
  // of the bounds: the compiler cannot tell that writing flags leaves them unchanged.)
  const CandidateBounds bounds(view, d, height_tolerance);
  const double ve = view.ve;
  for (std::size_t i = 0; i + 1 < length; ++i) {
    const double gc = (static_cast<double>(z[i + 1]) - static_cast<double>(z[i])) / d;
    flags[i] |= static_cast<std::uint8_t>(is_candidate_slope(gc, ve, bounds) * cell::candidate);
  }
}

}  // namespace tsk
