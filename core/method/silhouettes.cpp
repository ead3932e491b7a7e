// The entry points of the method: a DEM read window by window (what the front ends call), a
// grid held whole, and strips delivered by a reader.
#include "core/method/silhouettes.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "core/base/memory_budget.h"
#include "core/base/stage_timing.h"
#include "core/method/averaged_dem.h"
#include "core/method/plan_oblique.h"

namespace tsk {
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

EmptyRun empty_run(const StageStats& s) {
  if (s.factual_strokes + s.formulated_strokes > 0) return EmptyRun::not_empty;
  if (s.valid == 0) return EmptyRun::no_valid_cell;
  // Factual strokes start from occluding cells, formulated ones from the c-set through the filter.
  if (s.occluding == 0 && s.candidate == 0) return EmptyRun::nothing_seen;
  if (s.occluding == 0 && s.filtered == 0) return EmptyRun::all_filtered;
  return EmptyRun::all_short;
}

void stream_strips(SilhouetteStream& stream, const OrientedFrame& frame, std::size_t to,
                   std::size_t strip, const ProfileReader& read, unsigned threads) {
  check_strip_fits(frame, strip);
  // The strip of `count` profiles from `first`, with its neighbours.
  auto read_strip = [&](std::size_t first, std::size_t count, HeightGrid& heights) {
    const std::size_t lo = first > 0 ? first - 1 : 0;
    const std::size_t hi = std::min(frame.profiles, std::min(first + count, to) + 1);
    read(lo, hi - lo, heights);
  };
  // The first strip is an eighth of a strip, each next one twice the one before, up to a strip:
  // the stages start once an eighth is read, not a whole strip (on the 8000 x 8000 benchmark a
  // core stood idle for the 0.09 s the first strip took to read). Strips change no result.
  const auto after = [strip](std::size_t count) { return std::min(strip, 2 * count); };
  // The next strip is read while this one is processed, into memory of its own, by a reader of
  // its own.
  HeightGrid current, next;
  Worker reader(threads > 1);
  const std::size_t from = stream.next_profile();
  std::size_t count = std::max<std::size_t>(1, strip / 8);
  reader.run([&] { read_strip(from, count, current); }).get();
  for (std::size_t first = from; first < to; first += count, count = after(count)) {
    std::future<void> reading;
    if (first + count < to) {
      reading = reader.run([&, first, count] { read_strip(first + count, after(count), next); });
    }
    // If processing throws, the reader finishes the read before it goes.
    stream.add_strip(current, first, std::min(count, to - first));
    if (reading.valid()) reading.get();
    std::swap(current, next);
  }
}

SilhouetteResult run_in_strips(const OrientedFrame& frame, const GeoTransform& geotransform,
                               const ResolvedParams& params, double z_ref, std::size_t strip,
                               const ProfileReader& read, const ProgressFn& progress,
                               StrokeSink sink) {
  SilhouetteStream stream(frame, geotransform, params, z_ref, progress, std::move(sink));
  stream_strips(stream, frame, frame.profiles, strip, read, resolve_threads(params->threads));
  return stream.finish();
}

namespace {

SilhouetteResult sketch_source(const DemSource& dem, const SilhouetteParams& params,
                               std::size_t strip, const ProgressFn& progress, StrokeSink sink) {
  const OrientedFrame frame = make_frame(dem.grid, params.view.azimuth_deg);
  const ResolvedParams run = adapt_filter(params, dem.grid, dem.read, dem.read_alongside);
  // Plan-oblique geometry needs the DEM's lowest height before the first stroke: a pass of its
  // own over the DEM.
  const double z_ref = run->geometry == Geometry::oblique
                           ? dem_lowest_height(frame.dem_rows, frame.dem_cols, dem.read)
                           : 0.0;
  // Strips bound the memory, and they are faster than the whole DEM: the next strip is read while
  // the stages work on this one, into memory reused from strip to strip.
  StripLoader loader(frame, dem.read, run->threads);
  double reading = 0;
  SilhouetteResult result = run_in_strips(
      frame, dem.geotransform, run, z_ref, strip > 0 ? strip : strip_profiles(frame),
      [&](std::size_t first, std::size_t count, HeightGrid& heights) {
        const auto start = Clock::now();
        loader.load(first, count, heights);
        reading += seconds_since(start);
      },
      progress, std::move(sink));
  result.timings.reading = reading;
  return result;
}

}  // namespace

SilhouetteResult sketch_silhouettes(const DemSource& dem, const SilhouetteParams& params,
                                    std::size_t strip, const ProgressFn& progress,
                                    StrokeSink sink) {
  params.validate();
  const std::size_t factor = run_averaging(params, dem.grid, dem.geotransform);
  const DemGrid grid = averaged_grid(dem.grid, factor);
  SilhouetteResult result;
  if (factor > 1 &&
      within_run_budget(4.0 * static_cast<double>(grid.rows) * static_cast<double>(grid.cols))) {
    // The filter's survey, the plan-oblique reference and the strips each read the whole averaged
    // DEM: held, the DEM is read and averaged once, on two threads when it has two readers.
    const Clock::time_point start = Clock::now();
    const auto heights = std::make_shared<const HeightGrid>(
        read_averaged(dem, factor, progress_part(progress, 0.0, 0.5)));
    const double averaging = seconds_since(start);
    result =
        sketch_source(held_source(heights, grid, averaged_geotransform(dem.geotransform, factor)),
                      params, strip, progress_part(progress, 0.5, 1.0), std::move(sink));
    result.timings.reading += averaging;
  } else {
    result = sketch_source(averaged_dem(dem, factor), params, strip, progress, std::move(sink));
  }
  result.averaged = factor;
  return result;
}

SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const ResolvedParams& params,
                                 const ProgressFn& progress, std::optional<double> z_ref,
                                 StrokeSink sink) {
  if (oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("oriented grid does not match its frame");
  }
  SilhouetteStream stream(frame, geotransform, params,
                          z_ref ? *z_ref : plan_oblique_reference(oriented, params.params()),
                          progress, std::move(sink));
  stream.add_strip(oriented, 0, frame.profiles, true);
  return stream.finish();
}

}  // namespace tsk
