#include "slope_filter.h"

#include <cmath>

#include "candidates.h"

namespace tsk {

double row_slope(const HeightGrid& z, std::size_t p, std::size_t i, double w) {
  const float centre = z(p, i);
  if (!is_data(centre)) return std::numeric_limits<double>::quiet_NaN();
  const bool has_left = p > 0 && is_data(z(p - 1, i));
  const bool has_right = p + 1 < z.rows() && is_data(z(p + 1, i));
  if (has_left && has_right) {
    return (static_cast<double>(z(p + 1, i)) - static_cast<double>(z(p - 1, i))) / (2.0 * w);
  }
  if (has_right) return (static_cast<double>(z(p + 1, i)) - static_cast<double>(centre)) / w;
  if (has_left) return (static_cast<double>(centre) - static_cast<double>(z(p - 1, i))) / w;
  return 0.0;
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

void apply_slope_filter(const HeightGrid& z, double d, double w, const FilterParams& filter,
                        CellFlags& flags, unsigned threads, const ProgressFn& progress) {
  const std::size_t length = z.cols();
  parallel_for(
      z.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          const float* zp = z.row(p);
          std::uint8_t* fp = flags.row(p);
          for (std::size_t i = 0; i < length; ++i) {
            if ((fp[i] & (cell::candidate | cell::hidden)) != cell::candidate) continue;
            const double col_pct = std::fabs(column_slope(zp, length, i, d)) * 100.0;
            const double row_pct = std::fabs(row_slope(z, p, i, w)) * 100.0;
            if (filter_accepts(filter, col_pct, row_pct)) fp[i] |= cell::filtered;
          }
        }
      },
      progress);
}

}  // namespace tsk
