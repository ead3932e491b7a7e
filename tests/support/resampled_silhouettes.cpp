#include "resampled_silhouettes.h"

#include "core/base/errors.h"
#include "core/base/stage_timing.h"
#include "core/method/plan_oblique.h"

namespace tsk {

SilhouetteResult run_resampled_silhouettes(const HeightGrid& dem, const OrientedFrame& frame,
                                           const GeoTransform& geotransform,
                                           const SilhouetteParams& params,
                                           const ProgressFn& progress) {
  params.validate();
  if (!frame.resampled) throw Error("run_resampled_silhouettes needs a resampled frame");
  // Big enough for the linking of one batch to overlap the collection of the next (add_strip),
  // small enough to stay a few tens of megabytes on any DEM.
  constexpr std::size_t kStrip = 1024;
  double resampling = 0;
  SilhouetteResult result = run_in_strips(
      frame, geotransform, ResolvedParams(params), plan_oblique_reference(dem, params), kStrip,
      [&](std::size_t first, std::size_t count, HeightGrid& strip) {
        const auto start = Clock::now();
        resample_profiles(dem, frame, first, count, strip, params.threads);
        resampling += seconds_since(start);
      },
      progress);
  result.timings.resampling = resampling;
  return result;
}

}  // namespace tsk
