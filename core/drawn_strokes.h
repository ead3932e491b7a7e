// Drawn strokes (StrokeMode::drawn): the chains of a run turned into strokes a cartographer
// would publish. Joined where they visually continue, generalised after joining, smoothed within
// a tolerance of the exact chains, placed in the chosen geometry, run on at their ends if asked,
// and weighted for taper and depth (docs/DRAWN_STROKES.md).
#pragma once

#include <vector>

#include "frame.h"
#include "geotransform.h"
#include "params.h"
#include "strokes.h"

namespace tsk {

// What drawing needs of a run: its parameters in map units.
struct DrawingSetup {
  DrawnParams drawn;
  int min_cells = 3;
  double cell = 1.0;   // the view's spacing along profiles, map units
  double depth = 1.0;  // the view's depth, ground units (as StrokeVertex::dist)
  Geometry geometry = Geometry::map;
  // Plan-oblique geometry: the map offset of one cell along the line of sight, and what shifts a
  // point by how many cells.
  StrokePoint cell_step{0.0, 0.0};
  double cells_per_metre = 0.0;
  double z_ref = 0.0;
};

DrawingSetup drawing_setup(const OrientedFrame& frame, const GeoTransform& geotransform,
                           const SilhouetteParams& params, double z_ref);

// Draws the strokes of one class, built from every chain (none dropped yet) with their points in
// map geometry at sub-cell places and their vertices kept. Returns them in the order of their
// first pieces, each with its weights and without its vertices.
std::vector<Stroke> draw_strokes(std::vector<Stroke> strokes, const DrawingSetup& setup,
                                 unsigned threads);

}  // namespace tsk
