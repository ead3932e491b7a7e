// The classification of SPEC 1.2-1.6 written again from the SPEC's words, cell by cell and
// straightforwardly, sharing no code with the core: the oracle the pipeline's flags are held to.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/base/flags.h"
#include "core/method/params.h"

namespace tsk::oracle {

inline bool has_height(float z) {
  return std::isfinite(z);
}

// SPEC 1.3, the row slope as a fraction: central difference, one-sided at the grid's first and
// last profile and next to a nodata neighbour. Where neither neighbour has data the core takes
// the terrain as flat across (its documented choice where SPEC leaves the slope undefined).
inline double row_slope(const HeightGrid& z, std::size_t p, std::size_t i, double w) {
  const bool left = p > 0 && has_height(z(p - 1, i));
  const bool right = p + 1 < z.rows() && has_height(z(p + 1, i));
  const double centre = z(p, i);
  if (left && right) return (double(z(p + 1, i)) - double(z(p - 1, i))) / (2 * w);
  if (right) return (double(z(p + 1, i)) - centre) / w;
  if (left) return (centre - double(z(p - 1, i))) / w;
  return 0.0;
}

// SPEC 1.5: outside the removal polygon (0,0) (col_cut,0) ctrl (0,row_cut), or outside the
// rectangle of the cut-offs without diagonals; c and r in percent.
inline bool accepted(const FilterParams& f, double c, double r) {
  if (!f.diagonals) return !(c < f.col_cut_pct && r < f.row_cut_pct);
  const double ctrl_row = (f.col_cut_pct / f.row_cut_pct) * f.ctrl_col_pct;
  const double eq3 = f.row_cut_pct + (ctrl_row - f.row_cut_pct) / f.ctrl_col_pct * c;
  const double eq4 = ctrl_row * (f.col_cut_pct - c) / (f.col_cut_pct - f.ctrl_col_pct);
  return r > eq3 && r > eq4;
}

// SPEC 1.2: valid, hidden and occluding cells of profile p.
inline void classify_visibility(const HeightGrid& z, std::size_t p, double d,
                                const ViewParams& view, CellFlags& flags) {
  const double B = view.base_slope_pct / 100.0;
  double highest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < z.cols(); ++i) {
    if (!has_height(z(p, i))) continue;
    flags(p, i) |= cell::valid;
    const double t = view.ve * double(z(p, i)) + B * d * double(i);
    if (t < highest) flags(p, i) |= cell::hidden;
    if (t > highest) highest = t;
  }
  // Occluding: a visible cell whose next valid cell is hidden.
  std::size_t last_valid = z.cols();
  for (std::size_t i = 0; i < z.cols(); ++i) {
    if (!(flags(p, i) & cell::valid)) continue;
    if (last_valid < z.cols() && (flags(p, i) & cell::hidden) &&
        !(flags(p, last_valid) & cell::hidden)) {
      flags(p, last_valid) |= cell::occluding;
    }
    last_valid = i;
  }
}

// SPEC 1.4 and 1.5: the c-set, and of it the visible cells the filter accepts.
inline void select_and_filter(const HeightGrid& z, std::size_t p, double d, double w,
                              const SilhouetteParams& params, CellFlags& flags) {
  const double B = params.view.base_slope_pct / 100.0;
  for (std::size_t i = 0; i + 1 < z.cols(); ++i) {
    if (!has_height(z(p, i)) || !has_height(z(p, i + 1))) continue;  // gc undefined
    const double gc = (double(z(p, i + 1)) - double(z(p, i))) / d;
    if (!(-B < params.view.ve * gc && params.view.ve * gc < 0)) continue;
    flags(p, i) |= cell::candidate;
    if (flags(p, i) & cell::hidden) continue;
    const double c = std::fabs(gc) * 100, r = std::fabs(row_slope(z, p, i, w)) * 100;
    if (accepted(params.filter, c, r)) flags(p, i) |= cell::filtered;
  }
}

// SPEC 1.6: per zone of consecutive f-set cells, nothing when the cell right behind it occludes,
// else its far end (and its near end with near_and_far).
inline void thin(std::size_t p, Placement placement, CellFlags& flags) {
  const std::size_t L = flags.cols();
  for (std::size_t i = 0; i < L;) {
    if (!(flags(p, i) & cell::filtered)) {
      ++i;
      continue;
    }
    std::size_t last = i;
    while (last + 1 < L && (flags(p, last + 1) & cell::filtered)) ++last;
    const bool leads_to_factual = last + 1 < L && (flags(p, last + 1) & cell::occluding);
    if (!leads_to_factual) {
      flags(p, last) |= cell::thinned;
      if (placement == Placement::near_and_far) flags(p, i) |= cell::thinned;
    }
    i = last + 1;
  }
}

// Every stage of SPEC 1.2-1.6 on an oriented grid with spacings d (along) and w (across).
inline CellFlags classify(const HeightGrid& z, double d, double w, const SilhouetteParams& params) {
  CellFlags flags(z.rows(), z.cols(), 0);
  for (std::size_t p = 0; p < z.rows(); ++p) classify_visibility(z, p, d, params.view, flags);
  for (std::size_t p = 0; p < z.rows(); ++p) select_and_filter(z, p, d, w, params, flags);
  for (std::size_t p = 0; p < z.rows(); ++p) thin(p, params.placement, flags);
  return flags;
}

}  // namespace tsk::oracle
