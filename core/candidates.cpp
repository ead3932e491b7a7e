#include "candidates.h"

namespace tsk {

void select_candidates(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                       unsigned threads, const ProgressFn& progress) {
  const std::size_t length = z.cols();
  parallel_for(
      z.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          const float* zp = z.row(p);
          std::uint8_t* fp = flags.row(p);
          for (std::size_t i = 0; i + 1 < length; ++i) {
            // NaN slopes (nodata) fail both comparisons and are never candidates.
            if (is_candidate_slope(column_slope(zp, length, i, d), view)) fp[i] |= cell::candidate;
          }
        }
      },
      progress);
}

}  // namespace tsk
