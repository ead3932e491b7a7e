// A plotter's order for single-line paths: paths that meet are merged end to end, then drawn
// nearest first, each from whichever end is nearer, to cut the pen's travel in the air.
#pragma once

#include <vector>

#include "core/method/strokes.h"

namespace tsk {

struct PenPlan {
  std::vector<std::vector<StrokePoint>> paths;  // in drawing order, each drawn first to last
  double travel_before = 0.0;  // pen-up travel of the paths as given, from the start point
  double travel_after = 0.0;   // ... and as planned
};

// Pen-up travel drawing `paths` in order, each first to last, from `start`.
double pen_up_travel(const std::vector<std::vector<StrokePoint>>& paths, StrokePoint start);

// Merges paths whose ends lie within `meet` of each other (nearest first, never into a loop),
// then orders them greedily: from the pen's place, the nearest end of a path not yet drawn.
PenPlan plan_pen_paths(std::vector<std::vector<StrokePoint>> paths, double meet, StrokePoint start);

}  // namespace tsk
