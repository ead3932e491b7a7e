// Diagnostic (thesis figures 5.7 and 5.8): the scatter of column slope against row slope with the
// c-set highlighted, for the slope filter's removal region to be drawn over it, so a user tuning
// the control point can see what the filter does. io/pages/filter_diagram_page.h draws the page.
#pragma once

#include <string>
#include <vector>

#include "core/base/flags.h"
#include "core/method/params.h"
#include "core/method/silhouettes.h"

namespace tsk {

// Cell counts on a bins x bins grid over |column slope| in [0, max_pct) and |row slope| in
// [0, max_pct); slopes beyond fall in the last bin.
struct SlopeScatter {
  int bins = 0;
  double max_pct = 0.0;
  std::vector<std::size_t> all, candidate, filtered;  // row-major, row = row-slope bin
  std::size_t bin(double col_pct, double row_pct) const;
};

// The slope range a diagram of `filter` shows: 60 %, or 2.5 times the larger cut-off.
double diagram_range_pct(const FilterParams& filter);

SlopeScatter slope_scatter(const HeightGrid& z, const CellFlags& flags, double d, double w,
                           double max_pct, int bins = 120);

// The scatter of a run on a DEM held whole (its flags kept), over the range its filter's
// cut-offs call for: what both front ends draw.
SlopeScatter slope_scatter_of(const HeightGrid& oriented, const OrientedFrame& frame,
                              const SilhouetteResult& result);

}  // namespace tsk
