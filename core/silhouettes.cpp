#include "silhouettes.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>
#include <mutex>

#include "candidates.h"
#include "chaining.h"
#include "slope_filter.h"
#include "thinning.h"
#include "visibility.h"

namespace tsk {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Counts each classification bit over the grid and finds the lowest height.
void count_cells(const HeightGrid& z, const CellFlags& flags, unsigned threads, StageStats& stats,
                 double& z_min) {
  std::mutex merge;
  z_min = std::numeric_limits<double>::infinity();
  parallel_for(flags.rows(), threads, [&](std::size_t begin, std::size_t end) {
    StageStats local;
    float lowest = std::numeric_limits<float>::infinity();
    for (std::size_t p = begin; p < end; ++p) {
      const std::uint8_t* f = flags.row(p);
      const float* zp = z.row(p);
      for (std::size_t i = 0; i < flags.cols(); ++i) {
        const std::uint8_t v = f[i];
        if (!v) continue;
        local.valid += (v & cell::valid) != 0;
        local.hidden += (v & cell::hidden) != 0;
        local.occluding += (v & cell::occluding) != 0;
        local.candidate += (v & cell::candidate) != 0;
        local.filtered += (v & cell::filtered) != 0;
        local.thinned += (v & cell::thinned) != 0;
        lowest = std::min(lowest, zp[i]);
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    stats.valid += local.valid, stats.hidden += local.hidden, stats.occluding += local.occluding;
    stats.candidate += local.candidate, stats.filtered += local.filtered;
    stats.thinned += local.thinned;
    z_min = std::min(z_min, static_cast<double>(lowest));
  });
}

// Maps the progress of stage `index` of `count` onto the whole run.
ProgressFn stage_progress(const ProgressFn& progress, int index, int count) {
  if (!progress) return {};
  return [progress, index, count](double fraction) { return progress((index + fraction) / count); };
}

}  // namespace

std::vector<StageFigure> stage_figures(const StageStats& s) {
  return {{"hidden_pct", s.pct(s.hidden), false},
          {"occluding_pct", s.pct(s.occluding), false},
          {"cset_pct", s.pct(s.candidate), false},
          {"fset_pct", s.pct(s.filtered), false},
          {"tset_pct", s.pct(s.thinned), false},
          {"gset_pct", s.pct(s.generalised), false},
          {"factual_strokes", static_cast<double>(s.factual_strokes), true},
          {"formulated_strokes", static_cast<double>(s.formulated_strokes), true}};
}

SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const SilhouetteParams& params,
                                 const ProgressFn& progress) {
  params.validate();
  if (oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("oriented grid does not match its frame");
  }
  const unsigned threads = params.threads;
  const ViewParams& view = params.view;
  constexpr int kStages = 6;
  SilhouetteResult result;
  StageTimings& time = result.timings;
  CellFlags& flags = result.flags;

  auto start = Clock::now();
  classify_visibility(oriented, frame.d, view, flags, threads,
                      stage_progress(progress, 0, kStages));
  time.visibility = seconds_since(start);

  start = Clock::now();
  select_candidates(oriented, frame.d, view, flags, threads, stage_progress(progress, 1, kStages));
  time.candidates = seconds_since(start);

  start = Clock::now();
  apply_slope_filter(oriented, frame.d, frame.w, params.filter, flags, threads,
                     stage_progress(progress, 2, kStages));
  time.filter = seconds_since(start);

  start = Clock::now();
  thin(flags, params.placement, threads, stage_progress(progress, 3, kStages));
  time.thinning = seconds_since(start);

  start = Clock::now();
  const auto factual = chain_factual(flags, threads, stage_progress(progress, 4, kStages));
  const auto formulated = chain_formulated(flags, params.chain.window, threads);
  time.chaining = seconds_since(start);

  start = Clock::now();
  StageStats& stats = result.stats;
  double z_min = 0.0;
  count_cells(oriented, flags, threads, stats, z_min);
  const StrokeContext context{oriented,     flags,           frame,          view,
                              geotransform, params.geometry, params.subcell, z_min};
  make_strokes(factual, StrokeClass::factual, params.chain.min_cells, context, result.strokes,
               threads);
  stats.factual_strokes = result.strokes.size();
  make_strokes(formulated, StrokeClass::formulated, params.chain.min_cells, context, result.strokes,
               threads);
  stats.formulated_strokes = result.strokes.size() - stats.factual_strokes;
  for (const Stroke& s : result.strokes) stats.generalised += static_cast<std::size_t>(s.cells);
  time.strokes = seconds_since(start);
  if (progress && !progress(1.0)) throw Cancelled();
  return result;
}

}  // namespace tsk
