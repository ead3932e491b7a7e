// Stage 4 (SPEC 1.3, 1.5): row slopes and the slope filter that turns the c-set into the f-set.
#pragma once

#include <cstddef>
#include <limits>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/params.h"
#include "core/method/slope_scale_map.h"

namespace tsk {

// True slope across the line of sight at (p, i), central difference, one-sided at the first and
// last profile or next to a nodata neighbour. Where no neighbouring profile has data (a grid of
// one profile, an isolated strip) the terrain is taken as flat across: 0. NaN if z(p, i) is nodata.
double row_slope(const HeightGrid& z, std::size_t p, std::size_t i, double w);

// A profile with its neighbours, for the row slope: left or right is null at the grid's ends.
struct ProfileRows {
  const float* left;
  const float* centre;
  const float* right;
};
ProfileRows profile_rows(const HeightGrid& z, std::size_t p);

inline double row_slope(const ProfileRows& rows, std::size_t i, double w) {
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

// The filter's decision with its constants worked out once, for loops over many cells. The
// expressions are those of the thesis's equations 3 and 4, term for term.
class FilterRule {
 public:
  explicit FilterRule(const FilterParams& filter)
      : diagonals_(filter.diagonals),
        col_cut_(filter.col_cut_pct),
        row_cut_(filter.row_cut_pct),
        ctrl_row_(filter.ctrl_row_pct()),
        eq3_rate_((ctrl_row_ - row_cut_) / filter.ctrl_col_pct),
        eq4_run_(col_cut_ - filter.ctrl_col_pct) {}

  // True when (col_pct, row_pct) lies outside the removal polygon (0,0) (col_cut,0) ctrl
  // (0,row_cut), or outside the rectangle of the cut-offs when diagonals are off.
  bool accepts(double col_pct, double row_pct) const {
    // Both sides of each test are worked out (&, not &&): no branch on the outcome.
    if (!diagonals_) return !((col_pct < col_cut_) & (row_pct < row_cut_));
    const double eq3 = row_cut_ + eq3_rate_ * col_pct;
    const double eq4 = ctrl_row_ * (col_cut_ - col_pct) / eq4_run_;
    return (row_pct > eq3) & (row_pct > eq4);
  }

 private:
  bool diagonals_;
  double col_cut_, row_cut_, ctrl_row_, eq3_rate_, eq4_run_;
};

// Local adaptivity along one profile: the scale of its cells' neighbourhoods.
struct ProfileScales {
  const SlopeScaleMap& map;
  const OrientedFrame& frame;
  std::size_t profile;     // p
  std::size_t first_cell;  // the cell of the profile that index 0 of filter_profile stands for
  double at(std::size_t i) const {
    return map.scale_at(
        frame.to_pixel(static_cast<double>(profile), static_cast<double>(first_cell + i)));
  }
};

// Sets `filtered` on the visible c-set cells of one profile that the filter accepts. With
// `scales`, each cell's slopes are divided by its neighbourhood's scale first.
void filter_profile(const ProfileRows& rows, std::uint8_t* flags, std::size_t length, double d,
                    double w, const FilterParams& filter, const ProfileScales* scales = nullptr);

}  // namespace tsk
