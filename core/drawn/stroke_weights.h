// Drawn strokes, step 3: the weight of each point (taper towards the ends, depth cue towards the
// back of the view) and the optional over-extension of the ends.
#pragma once

#include "core/method/strokes.h"

namespace tsk {

// The weight at a stroke's very tips, of its full weight: a hand-drawn line starts thin, not at
// nothing.
constexpr double kTipWeight = 0.15;

struct WeightRule {
  double taper;      // share of the stroke's length over which each end thins, [0, 0.5]
  double depth_cue;  // weight lost from the front of the view (distance 0) to `depth`, [0, 1)
  double depth;      // depth of the view, ground units
};

// Sets stroke.weights: at each point the taper (kTipWeight at a tip rising to 1 at `taper` of the
// length from it, easing out as a pen does) times the depth cue (1 at the front, 1 - depth_cue at
// the back), from the points' arc length and their vertices' distances. Returns the length of the
// line the points draw (as polyline_length).
double weigh_stroke(Stroke& stroke, const WeightRule& rule);

// Extends both ends of a stroke of two or more points by `length` along the direction of its
// last `reach` of length, as a hand-drawn stroke runs on; the new points repeat their ends'
// vertices.
void extend_stroke(Stroke& stroke, double length, double reach);

}  // namespace tsk
