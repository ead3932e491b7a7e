// The method's run recipes: every front end (the command line, QGIS, the Python package) runs
// the method through these, so that a run is wired up in one place. A front end brings the DEM,
// the user's choices, its outputs and its own wording; the recipe resolves the filter on the DEM,
// sets what follows from the DEM (its ground scale, its lowest height) and runs the stages.
// sketch_silhouettes (silhouettes.h) is the recipe for a DEM read window by window.
#pragma once

#include "core/applications/drape.h"
#include "core/applications/profile_plot.h"
#include "core/applications/pstrokes.h"
#include "core/method/adaptive_filter.h"
#include "core/method/silhouettes.h"
#include "core/panorama/panorama.h"

namespace tsk {

// A DEM held whole, turned to a view, as a front end read it.
struct HeldDem {
  const HeightGrid& oriented;  // turned as `frame` says: its profiles x length
  OrientedFrame frame;         // the view it was turned for; a run must ask for the same azimuth
  // The georeferencing, and windows of the DEM on its own grid for the filter's survey. When the
  // grid is the DEM as it lies the survey reads the grid, and `source.read` may be empty.
  DemSource source;
  double lowest_height = 0.0;  // the DEM's lowest height, the plan-oblique reference (SPEC 1.9)
  double ground_scale = 1.0;   // ground metres per map unit of the DEM's CRS
};

// Windows of the DEM on its own grid: from memory when the grid is the DEM as it lies, else
// through the source (empty when it has none: then only a fixed filter resolves).
WindowReader dem_windows(const HeldDem& dem);

// The user's choice resolved on the DEM (adapt_filter).
ResolvedParams resolve_on(const HeldDem& dem, const SilhouetteParams& choice);

// Every stage on a DEM held whole, with every cell's class kept: what the classification, the
// filter diagram and the P-strokes start from. Throws Error on bad parameters or a DEM turned for
// another azimuth than the choice's, Cancelled when `progress` says stop. With a sink, strokes go
// to it as they complete (as sketch_silhouettes hands them on) and the result holds none.
SilhouetteResult sketch_held_dem(const HeldDem& dem, const SilhouetteParams& choice,
                                 const ProgressFn& progress = {}, StrokeSink sink = {});

// The strokes of a DEM held whole, as sketch_silhouettes draws them from its windows: drawn for a
// scale far coarser than the DEM, from the DEM averaged to that scale's cells (result.averaged;
// the result then holds no cell classes); otherwise as sketch_held_dem.
SilhouetteResult sketch_held_strokes(const HeldDem& dem, const SilhouetteParams& choice,
                                     const ProgressFn& progress = {}, StrokeSink sink = {});

// The drape's lattice for a DEM held whole: its visibility for the view, laid out in plan-oblique
// space about the DEM's lowest height. Throws Error as sketch_held_dem does.
PlanObliqueDrape lay_out_drape(const HeldDem& dem, const ViewParams& view, unsigned threads,
                               const ProgressFn& progress = {});

// The profile plot (SPEC 3) of a DEM held whole: every `every_n`-th cross-section, hidden parts
// removed. Throws Error as sketch_held_dem does.
std::vector<ProfileLine> plot_profiles(const HeldDem& dem, const ViewParams& view,
                                       std::size_t every_n, unsigned threads);

struct PStrokeRun {
  std::vector<PStroke> strokes;
  FilterReport filter;  // the slope filter the method ran with
};

// The P-stroke sketch (SPEC 3) of a DEM held whole: the method run with `choice` for its f-set,
// then the strokes across the view. Throws Error as sketch_held_dem does.
PStrokeRun sketch_pstrokes(const HeldDem& dem, const SilhouetteParams& choice,
                           const PStrokeParams& pstrokes, const ProgressFn& progress = {});

// What a panorama's user chooses. The method's view (azimuth, exaggeration, base slope) and
// geometry do not apply to a panorama; its filter, chaining, strokes, placement and threads do.
struct PanoramaChoice {
  PanoramaView view;  // its metres_per_unit is the DEM's, set by the recipe
  SilhouetteParams method;
  bool record_visibility = false;  // keep what a visibility raster needs
};

struct PanoramaRun {
  PanoramaResult result;
  FilterReport filter;
  // The panorama layer's: the view's, or one chosen for the panorama (panorama_exaggeration).
  double exaggeration = 1.0;
  // Wall seconds of the run's two steps, for --timings: the slope filter's survey of the DEM,
  // then the rays cast, classified and linked.
  double survey_seconds = 0.0, rays_seconds = 0.0;
};

// The panorama from the choice's viewpoint on a DEM held whole as it lies (the view from the west:
// its own grid). Drawn strokes are cut where their chains leap along the rays. Throws Error on a
// DEM not held as it lies or a view it cannot draw, Cancelled when `progress` says stop.
PanoramaRun sketch_panorama_on(const HeldDem& dem, const PanoramaChoice& choice,
                               const ProgressFn& progress = {});

}  // namespace tsk
