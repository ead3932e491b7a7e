#include "core/method/slope_filter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/method/candidates.h"

namespace tsk {

ProfileRows profile_rows(const HeightGrid& z, std::size_t p) {
  return {p > 0 ? z.row(p - 1) : nullptr, z.row(p), p + 1 < z.rows() ? z.row(p + 1) : nullptr};
}

double row_slope(const HeightGrid& z, std::size_t p, std::size_t i, double w) {
  return row_slope(profile_rows(z, p), i, w);
}

void filter_profile(const ProfileRows& profile, std::uint8_t* flags, std::size_t length, double d,
                    double w, const FilterParams& filter, const ProfileScales* scales) {
  // Local copies: the compiler cannot tell that writing flags leaves the arguments unchanged.
  const ProfileRows rows = profile;
  const FilterRule rule(filter);
  // Which cells are visible c-set cells is hard to predict, so a stretch of cells is first sifted
  // for them without branches, and only those are then filtered, also without branching on the
  // outcome.
  constexpr std::size_t kStretch = 256;
  std::uint32_t sifted[kStretch];
  for (std::size_t begin = 0; begin < length; begin += kStretch) {
    const std::size_t end = std::min(length, begin + kStretch);
    const std::size_t count = sift_cells(flags, begin, end, cell::candidate | cell::hidden,
                                         cell::candidate, begin, sifted);
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = begin + sifted[k];
      // Multiplying by exactly 1 without local scales leaves the slopes as they are.
      const double unscale = scales ? 1.0 / scales->at(i) : 1.0;
      const double col_pct = std::fabs(column_slope(rows.centre, length, i, d)) * 100.0 * unscale;
      const double row_pct = std::fabs(row_slope(rows, i, w)) * 100.0 * unscale;
      flags[i] |= static_cast<std::uint8_t>(rule.accepts(col_pct, row_pct) * cell::filtered);
    }
  }
}

}  // namespace tsk
