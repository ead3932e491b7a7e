#include "core/drawn/drawn_strokes.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "core/base/release_storage.h"
#include "core/drawn/drawing_scale.h"
#include "core/drawn/stroke_smoothing.h"
#include "core/drawn/stroke_weights.h"
#include "core/method/plan_oblique.h"

namespace tsk {

DrawingSetup drawing_setup(const OrientedFrame& frame, const GeoTransform& geotransform,
                           const SilhouetteParams& params, double z_ref) {
  DrawingSetup setup;
  setup.drawn = params.strokes;
  setup.min_cells = setup.least_piece_cells = params.chain.min_cells;
  setup.depth = frame.d * static_cast<double>(frame.length);
  setup.geometry = params.geometry;
  StrokePoint origin, one_cell;
  geotransform.apply(frame.to_pixel(0.0, 0.0), origin.x, origin.y);
  geotransform.apply(frame.to_pixel(0.0, 1.0), one_cell.x, one_cell.y);
  setup.cell_step = {one_cell.x - origin.x, one_cell.y - origin.y};
  setup.cell = distance({0.0, 0.0}, setup.cell_step);
  StrokePoint next_profile;
  geotransform.apply(frame.to_pixel(1.0, 0.0), next_profile.x, next_profile.y);
  setup.across = distance(origin, next_profile);
  setup.cells_per_metre = PlanObliqueShift(params.view, frame.d, z_ref)(0.0, z_ref + 1.0);
  setup.z_ref = z_ref;
  fit_to_scale(setup);
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

// Smooths, places, runs on and weighs one joined stroke; false when it outlines too little relief
// for the scale drawn for, and vanishes.
bool finish_stroke(Stroke& stroke, const DrawingSetup& setup) {
  const double relief = stroke_relief(stroke);
  if (relief < setup.relief_vanishing) return false;
  const DrawnParams& p = setup.drawn;
  // The exact places: each point's cell centre, the sub-cell offset along the profile undone.
  // Storage kept from stroke to stroke (one drawing thread at a time per drawer).
  thread_local std::vector<StrokePoint> centres;
  centres.resize(stroke.points.size());
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const double offset = stroke.vertices[k].offset;
    centres[k] = {stroke.points[k].x - setup.cell_step.x * offset,
                  stroke.points[k].y - setup.cell_step.y * offset};
  }
  smooth_stroke(stroke, p.smooth_cells * setup.cell, p.tolerance_cells * setup.cell,
                setup.geometry == Geometry::oblique, &centres);
  // The length attribute is the ground length of the line drawn in map geometry, without its
  // run-on: the line weighed, unless it moves or grows after smoothing.
  const bool moves = setup.geometry == Geometry::oblique || p.extend_cells > 0.0;
  if (moves) stroke.length = polyline_length(stroke.points);
  if (setup.geometry == Geometry::oblique) shift_plan_oblique(stroke, setup);
  extend_stroke(stroke, p.extend_cells * setup.cell, 3.0 * setup.cell);
  const double weighed_length = weigh_stroke(stroke, {p.taper, p.depth_cue, setup.depth});
  if (!moves) stroke.length = weighed_length;
  const double weight = relief_weight(relief, setup.relief_full);
  for (double& w : stroke.weights) w *= weight;
  release_storage(stroke.vertices);
  return true;
}

}  // namespace

StrokeDrawer::StrokeDrawer(const DrawingSetup& setup)
    : setup_(setup), rule_(join_rule(setup)), groups_(rule_) {}

double longest_step(const DrawingSetup& setup) {
  return kLeapCells * setup.cell;
}

JoinRule join_rule(const DrawingSetup& setup) {
  return {setup.drawn.join_gap_cells * setup.cell, setup.drawn.join_angle_deg,
          setup.least_piece_cells};
}

double join_reach_profiles(const DrawingSetup& setup) {
  return join_rule(setup).gap / std::max(setup.across, 1e-300) + 1.0;
}

double StrokeDrawer::longest_step() const {
  return tsk::longest_step(setup_);
}

void StrokeDrawer::prefetch(const Stroke& piece) const {
  if (piece.cells >= kLeastDrawnCells && rule_.gap > 0.0) groups_.prefetch(piece);
}

void StrokeDrawer::add(Stroke&& piece) {
  if (piece.cells < kLeastDrawnCells) return;
  if (rule_.gap > 0.0) groups_.add(piece);
  pending_.push_back(std::move(piece));
  drawn_.push_back(false);
}

void StrokeDrawer::take_settled(double frontier, StrokeGroups& groups) {
  // Groups are taken in the order of their first pieces, up to the first one still open to
  // pieces to come: its ends must lie farther than the gap from the frontier.
  const double settled_before = frontier - join_reach_profiles(setup_);
  while (!pending_.empty()) {
    const std::size_t first = first_pending_;
    if (rule_.gap > 0.0) {
      if (!(static_cast<double>(groups_.reach(first)) < settled_before)) break;
      groups_.take_group(first, members_);
    } else if (!(static_cast<double>(pending_.front().chain.back().p) < settled_before)) {
      break;
    } else {
      members_.assign(1, first);
    }
    // A piece alone and shorter than the shortest stroke is dropped here, as drawing would drop
    // it: a third of the pieces (2-cell ones mostly), no longer handed on to be dropped.
    const bool dropped =
        members_.size() == 1 && pending_[first - first_pending_].cells < setup_.min_cells;
    for (std::size_t id : members_) {
      if (!dropped) groups.pieces.push_back(std::move(pending_[id - first_pending_]));
      drawn_[id - first_pending_] = true;
    }
    if (!dropped) {
      groups.ends.push_back(groups.pieces.size());
      groups.firsts.push_back(first);
    }
    while (!drawn_.empty() && drawn_.front()) {
      pending_.pop_front();
      drawn_.pop_front();
      ++first_pending_;
    }
  }
  if (rule_.gap > 0.0) groups_.forget_before(first_pending_);
}

void StrokeDrawer::draw(StrokeGroups& groups, std::size_t from_group, std::size_t to_group,
                        const Out& out) const {
  std::size_t begin = from_group > 0 ? groups.ends[from_group - 1] : 0;
  for (std::size_t group = from_group; group < to_group; ++group) {
    const std::size_t end = groups.ends[group];
    const std::size_t first_piece = groups.firsts[group];
    const auto finish = [&](Stroke& stroke) {
      // The generalisation comes after joining: only pieces still short and alone are dropped.
      if (stroke.cells < setup_.min_cells || !finish_stroke(stroke, setup_)) return;
      out(first_piece, std::move(stroke));
    };
    const auto first = groups.pieces.begin() + static_cast<std::ptrdiff_t>(begin);
    if (end - begin > 1) {
      std::vector<Stroke> members(std::make_move_iterator(first),
                                  std::make_move_iterator(first + (end - begin)));
      for (Stroke& stroke : join_strokes(std::move(members), rule_)) finish(stroke);
    } else {
      finish(*first);
    }
    begin = end;
  }
}

}  // namespace tsk
