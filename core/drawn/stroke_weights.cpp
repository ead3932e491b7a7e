#include "core/drawn/stroke_weights.h"

#include <algorithm>
#include <cmath>

#include "core/drawn/stroke_smoothing.h"

namespace tsk {
namespace {

// The rise of the taper from a tip (u = 0) to full weight (u = 1): quick at first, like a pen
// touching down.
double taper_rise(double u) {
  const double v = 1.0 - std::clamp(u, 0.0, 1.0);
  return kTipWeight + (1.0 - kTipWeight) * (1.0 - v * v);
}

}  // namespace

double weigh_stroke(Stroke& stroke, const WeightRule& rule) {
  const std::size_t n = stroke.points.size();
  stroke.weights.assign(n, 1.0);
  double total = 0.0;
  std::vector<double>& w = stroke.weights;
  // First the arc length at each point (in w), then the weight.
  w[0] = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    total += distance(stroke.points[k - 1], stroke.points[k]);
    w[k] = total;
  }
  const double taper_length = rule.taper * total;
  const bool has_vertices = stroke.vertices.size() == n;
  for (std::size_t k = 0; k < n; ++k) {
    const double from_end = std::min(w[k], total - w[k]);
    const double taper = taper_length > 0.0 ? taper_rise(from_end / taper_length) : 1.0;
    const double dist = has_vertices ? stroke.vertices[k].dist : 0.0;
    const double depth =
        rule.depth > 0.0 ? 1.0 - rule.depth_cue * std::clamp(dist / rule.depth, 0.0, 1.0) : 1.0;
    w[k] = taper * depth;
  }
  return total;
}

namespace {

// The point a stroke's end runs on to: `length` beyond `end` along the direction from the point
// about `reach` before it.
template <typename It>
StrokePoint run_on(It end, It stop, double length, double reach) {
  const StrokePoint tip = *end;
  StrokePoint from = tip;
  double walked = 0.0;
  for (It it = std::next(end); it != stop && walked < reach; ++it) {
    walked += distance(from, *it);
    from = *it;
  }
  const double dx = tip.x - from.x, dy = tip.y - from.y, len = distance(from, tip);
  if (len <= 0.0) return tip;
  return {tip.x + dx / len * length, tip.y + dy / len * length};
}

}  // namespace

void extend_stroke(Stroke& stroke, double length, double reach) {
  std::vector<StrokePoint>& pts = stroke.points;
  if (pts.size() < 2 || !(length > 0.0)) return;
  const StrokePoint before = run_on(pts.begin(), pts.end(), length, reach);
  const StrokePoint after = run_on(pts.rbegin(), pts.rend(), length, reach);
  // Shifted up by one for the new first point (GCC 14 warns falsely about an insert here).
  pts.push_back(after);
  pts.push_back(after);
  std::move_backward(pts.begin(), pts.end() - 2, pts.end() - 1);
  pts.front() = before;
  if (!stroke.vertices.empty()) {
    const StrokeVertex first = stroke.vertices.front(), last = stroke.vertices.back();
    stroke.vertices.push_back(last);
    stroke.vertices.push_back(last);
    std::move_backward(stroke.vertices.begin(), stroke.vertices.end() - 2,
                       stroke.vertices.end() - 1);
    stroke.vertices.front() = first;
  }
}

}  // namespace tsk
