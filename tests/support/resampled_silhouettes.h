// The method on a DEM held in memory at a non-cardinal view, resampled strip by strip: for the
// tests, which compare it with the grid turned whole, and the benchmark's in-memory figures.
// (The front ends read their DEMs through sketch_silhouettes.)
#pragma once

#include "core/method/silhouettes.h"

namespace tsk {

// Runs every stage at a resampled (non-cardinal) view straight from the DEM (row 0 north),
// resampling a strip of profiles at a time into memory reused from strip to strip, so the
// line-of-sight grid is never held whole. Gives the strokes of run_silhouettes on
// orient(dem, frame), with the DEM's lowest height as the plan-oblique reference (SPEC 1.9).
SilhouetteResult run_resampled_silhouettes(const HeightGrid& dem, const OrientedFrame& frame,
                                           const GeoTransform& geotransform,
                                           const SilhouetteParams& params,
                                           const ProgressFn& progress = {});

}  // namespace tsk
