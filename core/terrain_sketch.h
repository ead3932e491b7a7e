// Terrain Sketch core: Factual and Formulated Silhouettes of a DEM seen obliquely from above.
// Table of contents, one line per stage (SPEC section in brackets), by family:
//
// method/ (the thesis's method):
//   orient.h          [1.1] DEM -> oriented grid g[p][i]: profiles left to right, cells front
//                     to back; frame.h (the view's map to DEM pixels), resample.h (bilinear,
//                     non-cardinal views), dem_windows.h (reading a DEM window by window)
//   visibility.h      [1.2] transformed heights, hidden cells, occluding cells, hidden zones
//   candidates.h      [1.3, 1.4] column slopes, the candidate set (c-set)
//   slope_filter.h    [1.3, 1.5] row slopes, the slope filter (f-set); adaptive_filter.h resolves
//                     the user's choice on the DEM (ResolvedParams)
//   thinning.h        [1.6] thinning rules (a) and (b) (t-set)
//   chaining.h        [1.7] factual and formulated chainers
//   strokes.h         [1.8, 1.9] strokes, attributes, generalisation, map/oblique geometry;
//                     scan_order.h (the strokes handed on in the order of the scan)
//   plan_oblique.h    [1.9] the plan-oblique shift and its reference height
//   silhouettes.h     [2] all stages in order with stage statistics and timings
//   run_recipes.h     the door every front end goes through (with sketch_silhouettes);
//                     run_note.h (the run in a sentence, for the outputs' metadata)
//
// drawn/: drawn strokes (docs/DRAWN_STROKES.md): grouping, joining, smoothing, weights, relief and
//   the scale drawn for (drawing_scale.h), outlines, the pen plotter's order, and the three
//   drawing threads (drawing_pipeline.h).
// panorama/: the method from a point observer: rays all round, earth curvature, the visibility
//   raster and peak labels (docs/PANORAMA.md).
// applications/: profile_plot.h, pstrokes.h, drape.h [3]; diagnostics.h (classification and row
//   slope maps); filter_diagram.h (column against row slope with the filter's removal region).
// base/: grid.h (the grid type, NaN nodata), flags.h (per-cell classification bits), errors.h,
//   parallel.h (threads, progress, cancellation), memory budgets (with a control group's limit)
//   and timing.
#pragma once

#include "core/applications/diagnostics.h"
#include "core/applications/drape.h"
#include "core/applications/filter_diagram.h"
#include "core/applications/profile_plot.h"
#include "core/applications/pstrokes.h"
#include "core/base/errors.h"
#include "core/base/flags.h"
#include "core/base/grid.h"
#include "core/base/parallel.h"
#include "core/method/candidates.h"
#include "core/method/chaining.h"
#include "core/method/orient.h"
#include "core/method/params.h"
#include "core/method/plan_oblique.h"
#include "core/method/silhouettes.h"
#include "core/method/slope_filter.h"
#include "core/method/strokes.h"
#include "core/method/thinning.h"
#include "core/method/visibility.h"
