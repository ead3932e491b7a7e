// Stage 4 (SPEC 1.3, 1.5): row slopes and the slope filter that turns the c-set into the f-set.
#pragma once

#include <cstddef>

#include "flags.h"
#include "parallel.h"
#include "params.h"

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
double row_slope(const ProfileRows& rows, std::size_t i, double w);

// The filter's decision for magnitudes of column and row slope in percent: true when the point
// lies outside the removal polygon (0,0) (col_cut,0) ctrl (0,row_cut), or outside the rectangle
// of the cut-offs when diagonals are off.
bool filter_accepts(const FilterParams& filter, double col_pct, double row_pct);

// Sets `filtered` on the visible c-set cells of one profile that the filter accepts.
void filter_profile(const ProfileRows& rows, std::uint8_t* flags, std::size_t length, double d,
                    double w, const FilterParams& filter);

// The same on every profile.
void apply_slope_filter(const HeightGrid& z, double d, double w, const FilterParams& filter,
                        CellFlags& flags, unsigned threads = 0, const ProgressFn& progress = {});

}  // namespace tsk
