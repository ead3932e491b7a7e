// Terrain Sketch core: Factual and Formulated Silhouettes of a DEM seen obliquely from above.
// Table of contents, one line per stage (SPEC section in brackets):
//
//   orient.h          [1.1] DEM -> oriented grid g[p][i]: profiles left to right, cells front
//                     to back; frame.h (the view's map to DEM pixels), resample.h (bilinear,
//                     non-cardinal views), dem_windows.h (reading a DEM window by window)
//   visibility.h      [1.2] transformed heights, hidden cells, occluding cells, hidden zones
//   candidates.h      [1.3, 1.4] column slopes, the candidate set (c-set)
//   slope_filter.h    [1.3, 1.5] row slopes, the slope filter (f-set)
//   thinning.h        [1.6] thinning rules (a) and (b) (t-set)
//   chaining.h        [1.7] factual and formulated chainers
//   strokes.h         [1.8, 1.9] strokes, attributes, generalisation, map/oblique geometry
//   plan_oblique.h    [1.9] the plan-oblique shift and its reference height
//   silhouettes.h     [2] all stages in order with stage statistics and timings
//
// Applications and diagnostics:
//   profile_plot.h    [3] cross-sections in plan-oblique geometry, hidden parts removed
//   pstrokes.h        [3] P-stroke sketch: Visvalingam effective areas, strokes across the view
//   drape.h           [3] any raster on the DEM grid projected into plan-oblique space
//   diagnostics.h     per-cell classification and row slope maps on the DEM grid
//   filter_diagram.h  column against row slope scatter with the filter's removal region (HTML)
//   panorama.h        the method from a point observer: rays all round, earth curvature, the
//                     visibility raster and peak labels (docs/PANORAMA.md)
//
// Support: grid.h (the grid type, NaN nodata), flags.h (per-cell classification bits),
// params.h (every parameter with its default), parallel.h (threads, progress, cancellation).
#pragma once

#include "candidates.h"
#include "chaining.h"
#include "diagnostics.h"
#include "drape.h"
#include "errors.h"
#include "filter_diagram.h"
#include "flags.h"
#include "grid.h"
#include "orient.h"
#include "parallel.h"
#include "params.h"
#include "plan_oblique.h"
#include "profile_plot.h"
#include "pstrokes.h"
#include "silhouettes.h"
#include "slope_filter.h"
#include "strokes.h"
#include "thinning.h"
#include "visibility.h"
