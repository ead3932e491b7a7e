// Drawn strokes, step 2: smoothing along the stroke, within a tolerance of its exact places.
#pragma once

#include <vector>

#include "strokes.h"

namespace tsk {

// Smooths a stroke's points (and its vertices' distances and heights, which plan-oblique geometry
// and depth cueing read) with a Gaussian of `sigma` map units along its arc length; the end
// points stay. A point never moves farther than `tolerance` from where it was: smoothing rounds
// the cell grid's stair steps but does not invent terrain.
void smooth_stroke(Stroke& stroke, double sigma, double tolerance);

// The length of a polyline.
double polyline_length(const std::vector<StrokePoint>& points);

}  // namespace tsk
