#include "core/method/run_recipes.h"

#include <utility>

#include "core/base/errors.h"
#include "core/base/stage_timing.h"
#include "core/method/averaged_dem.h"
#include "core/method/dem_windows.h"
#include "core/method/visibility.h"

namespace tsk {

namespace {

// Refuses a run whose view is not the one the DEM was turned for.
void require_view(const HeldDem& dem, const ViewParams& view) {
  view.validate();
  const OrientedFrame asked = make_frame(dem.frame.dem_grid(), view.azimuth_deg);
  if (asked.azimuth_deg != dem.frame.azimuth_deg || asked.resampled != dem.frame.resampled) {
    throw Error("internal: the DEM was turned for azimuth " + number_text(dem.frame.azimuth_deg) +
                ", the run asks for " + number_text(view.azimuth_deg));
  }
}

// The visibility of every cell of the held DEM for `view`, which must be the one it was turned for.
CellFlags visibility_of(const HeldDem& dem, const ViewParams& view, unsigned threads) {
  require_view(dem, view);
  CellFlags flags;
  classify_visibility(dem.oriented, dem.frame.d, view, flags, threads);
  return flags;
}

}  // namespace

WindowReader dem_windows(const HeldDem& dem) {
  if (!dem.frame.as_it_lies()) return dem.source.read;
  const HeightGrid& grid = dem.oriented;
  return [&grid](const DemWindow& w, float* heights) { copy_window(grid, w, heights); };
}

ResolvedParams resolve_on(const HeldDem& dem, const SilhouetteParams& choice) {
  return adapt_filter(choice, dem.source.grid, dem_windows(dem));
}

SilhouetteResult sketch_held_dem(const HeldDem& dem, const SilhouetteParams& choice,
                                 const ProgressFn& progress, StrokeSink sink) {
  require_view(dem, choice.view);
  const ResolvedParams params = resolve_on(dem, choice);
  return run_silhouettes(dem.oriented, dem.frame, dem.source.geotransform, params, progress,
                         dem.lowest_height, std::move(sink));
}

SilhouetteResult sketch_held_strokes(const HeldDem& dem, const SilhouetteParams& choice,
                                     const ProgressFn& progress, StrokeSink sink) {
  require_view(dem, choice.view);
  if (run_averaging(choice, dem.source.grid, dem.source.geotransform) == 1)
    return sketch_held_dem(dem, choice, progress, std::move(sink));
  DemSource windows = dem.source;
  windows.read = dem_windows(dem);
  if (!windows.read) throw Error("the DEM held has no windows to average for the scale drawn for");
  return sketch_silhouettes(windows, choice, 0, progress, std::move(sink));
}

PlanObliqueDrape lay_out_drape(const HeldDem& dem, const ViewParams& view, unsigned threads,
                               const ProgressFn& progress) {
  return PlanObliqueDrape(dem.oriented, visibility_of(dem, view, threads), dem.frame, view,
                          dem.lowest_height, progress, threads);
}

std::vector<ProfileLine> plot_profiles(const HeldDem& dem, const ViewParams& view,
                                       std::size_t every_n, unsigned threads) {
  return profile_plot(dem.oriented, visibility_of(dem, view, threads), dem.frame, view,
                      dem.source.geotransform, every_n, dem.lowest_height);
}

PStrokeRun sketch_pstrokes(const HeldDem& dem, const SilhouetteParams& choice,
                           const PStrokeParams& pstrokes, const ProgressFn& progress) {
  pstrokes.validate();
  const SilhouetteResult result = sketch_held_dem(dem, choice, progress_part(progress, 0.0, 0.7));
  return {pstroke_sketch(dem.oriented, result.flags, dem.frame, choice.view,
                         dem.source.geotransform, choice.geometry, pstrokes, dem.lowest_height,
                         choice.threads, progress_part(progress, 0.7, 1.0)),
          result.filter};
}

PanoramaRun sketch_panorama_on(const HeldDem& dem, const PanoramaChoice& choice,
                               const ProgressFn& progress) {
  if (!dem.frame.as_it_lies())
    throw Error("internal: a panorama needs the DEM as it lies, unturned");
  const Clock::time_point start = Clock::now();
  const ResolvedParams resolved = resolve_on(dem, choice.method);
  const double survey_seconds = seconds_since(start);
  const SilhouetteParams& method = resolved.params();
  PanoramaParams params;
  params.view = choice.view;
  params.view.metres_per_unit = dem.ground_scale;
  params.rules = {method.filter, method.height_tolerance, method.placement};
  params.local_scale = method.local_scale;
  params.chain = method.chain;
  params.threads = method.threads;
  params.record_visibility = choice.record_visibility;
  // A leap along a ray draws no line on the terrain; SPEC's exact strokes are the chains.
  params.cut_leaps = method.strokes.drawn();
  const Clock::time_point rays_start = Clock::now();
  PanoramaResult result = sketch_panorama(dem.oriented, dem.source.geotransform, params, progress);
  const double rays_seconds = seconds_since(rays_start);
  const double exaggeration = panorama_exaggeration(result, choice.view.exaggeration);
  return {std::move(result), resolved.filter(), exaggeration, survey_seconds, rays_seconds};
}

}  // namespace tsk
