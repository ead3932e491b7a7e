// What a run reports: the cell counts of each stage (SPEC 2) and the time each stage took.
#pragma once

#include <cstddef>
#include <vector>

namespace tsk {

// Cell counts of each stage (SPEC 2); shares are of the valid cells.
struct StageStats {
  std::size_t valid = 0;
  std::size_t hidden = 0;
  std::size_t occluding = 0;
  std::size_t candidate = 0;    // c-set
  std::size_t filtered = 0;     // f-set
  std::size_t thinned = 0;      // t-set
  std::size_t generalised = 0;  // g-set: cells of kept strokes, factual and formulated
  std::size_t factual_strokes = 0;
  std::size_t formulated_strokes = 0;
  double pct(std::size_t n) const { return valid ? 100.0 * static_cast<double>(n) / valid : 0.0; }
};

// The figures of SPEC 2 under their report keys (hidden_pct ... gset_pct in percent of valid
// cells, then factual_strokes and formulated_strokes), in report order.
struct StageFigure {
  const char* key;
  double value;
  bool is_count;
};
std::vector<StageFigure> stage_figures(const StageStats& stats);

// Why a run drew no stroke at all: the first stage that left nothing to draw, so that the user is
// told what to change rather than handed empty layers without a word.
enum class EmptyRun {
  not_empty,      // it drew strokes
  no_valid_cell,  // every cell of the DEM is nodata (declared, or NaN)
  nothing_seen,   // no cell hides another or is seen edge-on (flat, or too gentle for the view)
  all_filtered,   // the slope filter removed every candidate, and no cell hides another
  all_short,      // chains were made, each shorter than the shortest stroke kept
};
EmptyRun empty_run(const StageStats& stats);

// Wall time of each stage, seconds. The stages run profile by profile, interleaved, so the
// wall time of the whole is split between them by their shares of the threads' time.
struct StageTimings {
  double visibility = 0, candidates = 0, filter = 0, thinning = 0, chaining = 0, strokes = 0;
  // Reading the DEM (sketch_silhouettes) and resampling it strip by strip (tests, benchmark),
  // each strip while the stages work on the one before: time alongside the stages, not added to
  // them.
  double reading = 0, resampling = 0;
};

}  // namespace tsk
