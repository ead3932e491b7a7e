#include "candidates.h"

#include "vector_clones.h"

namespace tsk {

TSK_VECTOR_CLONES
void select_profile_candidates(const float* z, std::uint8_t* flags, std::size_t length, double d,
                               const ViewParams& view) {
  // is_candidate_slope(column_slope(...)) without branches, so that it vectorises. Its nodata
  // checks are not needed: with ve > 0 and d > 0, a NaN or infinite height at either end gives a
  // NaN or infinite exaggerated slope, which fails one of the two comparisons.
  const double ve = view.ve, steepest = -view.base_slope();
  for (std::size_t i = 0; i + 1 < length; ++i) {
    const double exaggerated =
        ve * ((static_cast<double>(z[i + 1]) - static_cast<double>(z[i])) / d);
    const bool candidate = (exaggerated < 0.0) & (exaggerated > steepest);
    flags[i] |= static_cast<std::uint8_t>(candidate * cell::candidate);
  }
}

void select_candidates(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                       unsigned threads, const ProgressFn& progress) {
  const std::size_t length = z.cols();
  parallel_for(
      z.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
          select_profile_candidates(z.row(p), flags.row(p), length, d, view);
      },
      progress);
}

}  // namespace tsk
