#include "drawn_strokes.h"

#include <algorithm>
#include <cmath>

#include "parallel.h"
#include "plan_oblique.h"
#include "stroke_joining.h"
#include "stroke_smoothing.h"
#include "stroke_weights.h"

namespace tsk {

DrawingSetup drawing_setup(const OrientedFrame& frame, const GeoTransform& geotransform,
                           const SilhouetteParams& params, double z_ref) {
  DrawingSetup setup;
  setup.drawn = params.strokes;
  setup.min_cells = params.chain.min_cells;
  setup.depth = frame.d * static_cast<double>(frame.length);
  setup.geometry = params.geometry;
  StrokePoint origin, one_cell;
  geotransform.apply(frame.to_pixel(0.0, 0.0), origin.x, origin.y);
  geotransform.apply(frame.to_pixel(0.0, 1.0), one_cell.x, one_cell.y);
  setup.cell_step = {one_cell.x - origin.x, one_cell.y - origin.y};
  setup.cell = std::hypot(setup.cell_step.x, setup.cell_step.y);
  setup.cells_per_metre = PlanObliqueShift(params.view, frame.d, z_ref)(0.0, z_ref + 1.0);
  setup.z_ref = z_ref;
  return setup;
}

namespace {

// Moves each point of a stroke in map geometry to where plan-oblique geometry draws it.
void shift_plan_oblique(Stroke& stroke, const DrawingSetup& setup) {
  for (std::size_t k = 0; k < stroke.points.size(); ++k) {
    const double cells = setup.cells_per_metre * (stroke.vertices[k].z - setup.z_ref);
    stroke.points[k].x += setup.cell_step.x * cells;
    stroke.points[k].y += setup.cell_step.y * cells;
  }
}

// Smooths, places, runs on and weighs one joined stroke.
void finish_stroke(Stroke& stroke, const DrawingSetup& setup) {
  const DrawnParams& p = setup.drawn;
  smooth_stroke(stroke, p.smooth_cells * setup.cell, p.tolerance_cells * setup.cell);
  stroke.length = polyline_length(stroke.points);  // the drawn line's ground length
  if (setup.geometry == Geometry::oblique) shift_plan_oblique(stroke, setup);
  extend_stroke(stroke, p.extend_cells * setup.cell, 3.0 * setup.cell);
  weigh_stroke(stroke, {p.taper, p.depth_cue, setup.depth});
  stroke.vertices = {};
}

}  // namespace

std::vector<Stroke> draw_strokes(std::vector<Stroke> strokes, const DrawingSetup& setup,
                                 unsigned threads) {
  const DrawnParams& p = setup.drawn;
  if (p.join_gap_cells > 0.0)
    strokes = join_strokes(std::move(strokes), {p.join_gap_cells * setup.cell, p.join_angle_deg});
  // The generalisation comes after joining: only pieces still short and alone are dropped.
  strokes.erase(std::remove_if(strokes.begin(), strokes.end(),
                               [&](const Stroke& s) { return s.cells < setup.min_cells; }),
                strokes.end());
  parallel_for(strokes.size(), threads, [&](std::size_t lo, std::size_t hi) {
    for (std::size_t k = lo; k < hi; ++k) finish_stroke(strokes[k], setup);
  });
  return strokes;
}

}  // namespace tsk
