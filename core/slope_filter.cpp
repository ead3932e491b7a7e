#include "slope_filter.h"

#include <cmath>

#include "candidates.h"

namespace tsk {

ProfileRows profile_rows(const HeightGrid& z, std::size_t p) {
  return {p > 0 ? z.row(p - 1) : nullptr, z.row(p), p + 1 < z.rows() ? z.row(p + 1) : nullptr};
}

double row_slope(const ProfileRows& rows, std::size_t i, double w) {
  const float centre = rows.centre[i];
  if (!is_data(centre)) return std::numeric_limits<double>::quiet_NaN();
  const bool has_left = rows.left && is_data(rows.left[i]);
  const bool has_right = rows.right && is_data(rows.right[i]);
  if (has_left && has_right) {
    return (static_cast<double>(rows.right[i]) - static_cast<double>(rows.left[i])) / (2.0 * w);
  }
  if (has_right) return (static_cast<double>(rows.right[i]) - static_cast<double>(centre)) / w;
  if (has_left) return (static_cast<double>(centre) - static_cast<double>(rows.left[i])) / w;
  return 0.0;
}

double row_slope(const HeightGrid& z, std::size_t p, std::size_t i, double w) {
  return row_slope(profile_rows(z, p), i, w);
}

bool filter_accepts(const FilterParams& filter, double col_pct, double row_pct) {
  if (!filter.diagonals) return !(col_pct < filter.col_cut_pct && row_pct < filter.row_cut_pct);
  const double ctrl_col = filter.ctrl_col_pct;
  const double ctrl_row = filter.ctrl_row_pct();
  // Thesis equations 3 and 4: the lines from each cut-off to the control point.
  const double eq3 = filter.row_cut_pct + (ctrl_row - filter.row_cut_pct) / ctrl_col * col_pct;
  const double eq4 = ctrl_row * (filter.col_cut_pct - col_pct) / (filter.col_cut_pct - ctrl_col);
  return row_pct > eq3 && row_pct > eq4;
}

void filter_profile(const ProfileRows& rows, std::uint8_t* flags, std::size_t length, double d,
                    double w, const FilterParams& filter) {
  for (std::size_t i = 0; i < length; ++i) {
    if ((flags[i] & (cell::candidate | cell::hidden)) != cell::candidate) continue;
    const double col_pct = std::fabs(column_slope(rows.centre, length, i, d)) * 100.0;
    const double row_pct = std::fabs(row_slope(rows, i, w)) * 100.0;
    if (filter_accepts(filter, col_pct, row_pct)) flags[i] |= cell::filtered;
  }
}

void apply_slope_filter(const HeightGrid& z, double d, double w, const FilterParams& filter,
                        CellFlags& flags, unsigned threads, const ProgressFn& progress) {
  const std::size_t length = z.cols();
  parallel_for(
      z.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
          filter_profile(profile_rows(z, p), flags.row(p), length, d, w, filter);
      },
      progress);
}

}  // namespace tsk
