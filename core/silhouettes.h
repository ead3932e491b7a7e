// The whole method in order (SPEC 1.2-1.9 and 2), one named step per stage.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "flags.h"
#include "orient.h"
#include "parallel.h"
#include "params.h"
#include "strokes.h"

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

// Wall time of each stage, seconds. The stages run profile by profile, interleaved, so the
// wall time of the whole is split between them by their shares of the threads' time.
struct StageTimings {
  double visibility = 0, candidates = 0, filter = 0, thinning = 0, chaining = 0, strokes = 0;
  // Turning the DEM strip by strip (run_resampled_silhouettes), each strip while the stages work
  // on the one before: time alongside the stages, not added to them.
  double resampling = 0;
};

struct SilhouetteResult {
  std::vector<Stroke> strokes;  // factual first, then formulated
  StageStats stats;
  StageTimings timings;
  CellFlags flags;  // the per-cell classification, for diagnostics and tests
};

// Takes each stroke as soon as it is complete and every stroke of its class started before it has
// been handed on: factual and formulated strokes each in the order of SPEC 1.7's scan, the two
// classes interleaved. Called from a linking thread, one call at a time; what it throws ends the
// run.
using StrokeSink = std::function<void(Stroke&& stroke)>;

// Runs the stages on profiles delivered in strips, left to right, holding one strip at a time:
// for DEMs larger than memory. Memory beyond the strip is that of the strokes, unless a sink
// takes them as they complete. run_silhouettes is one strip.
class SilhouetteStream {
 public:
  // z_ref: the DEM's lowest height (plan-oblique geometry needs it before the first strip).
  // With a sink, strokes go to it and the result holds none.
  SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                   const SilhouetteParams& params, double z_ref, const ProgressFn& progress = {},
                   StrokeSink sink = {});
  ~SilhouetteStream();

  // Profiles [first, first + count) with their neighbours for the row slope: `z` holds profiles
  // [first - 1, first + count + 1), without the ones beyond the grid's ends. Strips must follow
  // each other without gaps. keep_flags: hand this strip's classification to the result (for a
  // single strip covering the grid).
  void add_strip(const HeightGrid& z, std::size_t first, std::size_t count,
                 bool keep_flags = false);
  SilhouetteResult finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Reads oriented profiles [first, first + count) of the grid (a strip with its neighbours) into
// `strip`, which holds the previous strip: a reader may reuse its memory.
using ProfileReader = std::function<void(std::size_t first, std::size_t count, HeightGrid& strip)>;

// The whole method with the grid read `strip` profiles at a time through `read`, each strip with
// the neighbouring profiles the row slope needs. Equal to run_silhouettes on the whole grid.
// With a sink, strokes go to it as they complete and the result holds none.
SilhouetteResult run_in_strips(const OrientedFrame& frame, const GeoTransform& geotransform,
                               const SilhouetteParams& params, double z_ref, std::size_t strip,
                               const ProfileReader& read, const ProgressFn& progress = {},
                               StrokeSink sink = {});

// True when turning a whole DEM for this view and classifying it would take more than half of
// this machine's memory: the turned grid at 5 bytes a cell and, resampled, the DEM beside it at 4.
// Reading that much could not fail cleanly: memory is promised freely and taken at first use.
bool too_large_to_turn_whole(const OrientedFrame& frame);

// Profiles per strip for a strip-by-strip run of this view: 1024, more for profiles under 1024
// cells (1 Mi cells a strip, up to 65536 profiles), fewer for profiles so long that a run's
// strips (two of heights, the classification and, resampled, the band: 9 or 13 bytes a cell)
// would pass 512 MiB, at least 16.
std::size_t strip_profiles(const OrientedFrame& frame);

// Runs every stage on an oriented grid (see orient.h). z_ref is the DEM's lowest height, the
// plan-oblique reference; without it the grid's lowest height stands in (in oblique geometry),
// which is the DEM's for a cardinal view but may lie above it for a resampled one. Throws Error on
// bad parameters or a grid that does not match the frame, Cancelled when `progress` returns false.
SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const SilhouetteParams& params,
                                 const ProgressFn& progress = {},
                                 std::optional<double> z_ref = std::nullopt);

// Runs every stage at a resampled (non-cardinal) view straight from the DEM (row 0 north),
// resampling a strip of profiles at a time into memory reused from strip to strip, so the
// line-of-sight grid is never held whole. Gives the strokes of run_silhouettes on
// orient(dem, frame), with the DEM's lowest height as the plan-oblique reference (SPEC 1.9).
SilhouetteResult run_resampled_silhouettes(const HeightGrid& dem, const OrientedFrame& frame,
                                           const GeoTransform& geotransform,
                                           const SilhouetteParams& params,
                                           const ProgressFn& progress = {});

}  // namespace tsk
