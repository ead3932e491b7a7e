// The method on one profile (SPEC 1.2-1.7): the stages that classify its cells, the counts of
// each stage, and the chain candidates with the stroke cells they stand for. SilhouetteStream runs
// these on every profile of a strip, while its cells are in cache.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/base/grid.h"
#include "core/base/stage_timing.h"
#include "core/method/chaining.h"
#include "core/method/frame.h"
#include "core/method/params.h"
#include "core/method/stage_stats.h"
#include "core/method/strokes.h"

namespace tsk {

// Cells [begin, end) of a profile: from its first to its last cell with data.
struct CellRange {
  std::size_t begin = 0, end = 0;
  std::size_t size() const { return end - begin; }
};

// SPEC 1.2-1.6 on profile p, row `row` of strip `z` (its neighbours' rows beside it for the row
// slope): sets its flags `f` (frame.length of them) and returns the cells with data, which the
// stages keep to. Each stage is timed on `clock`.
CellRange classify_profile(const HeightGrid& z, std::size_t row, std::size_t p, std::uint8_t* f,
                           const OrientedFrame& frame, const SilhouetteParams& params,
                           StageClock& clock);

// Adds the classification counts of the flags of `length` cells to `stats`.
void count_profile(const std::uint8_t* f, std::size_t length, StageStats& stats);

// Adds the per-cell counts of `counts` (not the strokes) to `stats`.
void add_counts(const StageStats& counts, StageStats& stats);

// The chain candidates of one profile for both chainers (SPEC 1.7) and the stroke cells they
// stand for (SPEC 1.8), collected in parallel and linked in order. Refilled profile after
// profile, its storage reused.
struct ProfileChainCells {
  ProfileCandidates factual, formulated;
  std::vector<StrokeCell> factual_cells, formulated_cells;

  // From the flags `f` of profile p (strip row `row`), cells `cells` of it.
  void collect(const StrokeContext& context, const std::uint8_t* f, std::size_t p, CellRange cells);
};

}  // namespace tsk
