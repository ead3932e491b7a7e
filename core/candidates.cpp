#include "candidates.h"

namespace tsk {

void select_profile_candidates(const float* z, std::uint8_t* flags, std::size_t length, double d,
                               const ViewParams& view) {
  for (std::size_t i = 0; i + 1 < length; ++i) {
    // NaN slopes (nodata) fail both comparisons and are never candidates.
    if (is_candidate_slope(column_slope(z, length, i, d), view)) flags[i] |= cell::candidate;
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
