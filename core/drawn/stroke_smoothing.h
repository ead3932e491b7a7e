// Drawn strokes, step 2: smoothing along the stroke, within a tolerance of its exact places.
#pragma once

#include <cmath>
#include <vector>

#include "core/method/strokes.h"

namespace tsk {

// Smooths a stroke's points with a Gaussian of `sigma` map units along it, taken over its points
// at their mean spacing; the end points stay. A point never ends farther than `tolerance` from
// its anchor (where it was, if no anchors are given; its cell's centre for drawn strokes):
// smoothing rounds the cell grid's stair steps but does not invent terrain. heights: smooth its
// vertices' heights alike, for plan-oblique geometry to place the points by.
void smooth_stroke(Stroke& stroke, double sigma, double tolerance, bool heights = false,
                   const std::vector<StrokePoint>* anchors = nullptr);

// The length of a polyline.
double polyline_length(const std::vector<StrokePoint>& points);

}  // namespace tsk
