// The per-profile stages of the core run over a whole oriented grid, one stage at a time: for the
// stage tests and the benchmark's stage timings. The shipped pipeline runs the stages profile by
// profile instead (core/profile_stages.h).
#pragma once

#include <vector>

#include "core/base/flags.h"
#include "core/base/parallel.h"
#include "core/method/candidates.h"
#include "core/method/chaining.h"
#include "core/method/params.h"
#include "core/method/slope_filter.h"
#include "core/method/thinning.h"

namespace tsk {

// SPEC 1.4: the c-set on every profile.
void select_candidates(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                       unsigned threads = 0);

// SPEC 1.5: the slope filter on every profile.
void apply_slope_filter(const HeightGrid& z, double d, double w, const FilterParams& filter,
                        CellFlags& flags, unsigned threads = 0);

// SPEC 1.6: the thinning rules on every profile.
void thin(CellFlags& flags, Placement placement, unsigned threads = 0);

// The filter's decision for magnitudes of column and row slope in percent (FilterRule::accepts).
inline bool filter_accepts(const FilterParams& filter, double col_pct, double row_pct) {
  return FilterRule(filter).accepts(col_pct, row_pct);
}

// SPEC 1.7 over a whole classified grid, through the linker.
// Factual Silhouettes: an occluding cell links to the unused occluding cell on the next profile
// whose [cell, end of hidden zone] interval overlaps its own, nearest first, ties to the front.
std::vector<Chain> chain_factual(const CellFlags& flags);

// Formulated Silhouettes: a t-set cell links to the unused t-set cell on the next profile within
// `window` cells, nearest first, ties to the front. Chains of one cell are never returned.
std::vector<Chain> chain_formulated(const CellFlags& flags, int window);

}  // namespace tsk
