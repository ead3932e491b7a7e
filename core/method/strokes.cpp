#include "core/method/strokes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/method/candidates.h"
#include "core/method/plan_oblique.h"
#include "core/method/slope_filter.h"
#include "core/method/visibility.h"

namespace tsk {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

const char* stroke_class_name(StrokeClass cls) {
  return cls == StrokeClass::factual ? "factual" : "formulated";
}

const std::vector<StrokeRealField>& stroke_real_fields() {
  static const std::vector<StrokeRealField> fields = {
      {"length", &Stroke::length},
      {"mean_slope", &Stroke::mean_slope_pct},
      {"mean_row_slope", &Stroke::mean_row_slope_pct},
      {"mean_depth", &Stroke::mean_depth_m},
      {"max_depth", &Stroke::max_depth_m},
      {"mean_dist", &Stroke::mean_dist},
      {"mean_z", &Stroke::mean_z},
  };
  return fields;
}

double subcell_peak(const float* z, std::size_t length, std::size_t i, double d,
                    const ViewParams& view) {
  const double at = static_cast<double>(i);
  if (i == 0 || i + 1 >= length || !is_data(z[i - 1]) || !is_data(z[i + 1])) return at;
  const double before = transformed_height(z[i - 1], i - 1, d, view);
  const double here = transformed_height(z[i], i, d, view);
  const double after = transformed_height(z[i + 1], i + 1, d, view);
  const double curvature = before - 2.0 * here + after;
  if (!(curvature < 0.0)) return at;  // not a peak
  const double offset = 0.5 * (before - after) / curvature;
  return at + std::clamp(offset, -0.5, 0.5);
}

double subcell_break(const float* z, const std::uint8_t* flags, std::size_t length, std::size_t i,
                     double d, double ve, const CandidateBounds& bounds) {
  const double at = static_cast<double>(i);
  const auto in_zone = [&](std::size_t k) { return k < length && (flags[k] & cell::filtered); };
  // The zone's edge this cell stands for: the far one, or the near one for a near-end cell.
  const bool far_edge = !in_zone(i + 1);
  // Inside the zone there is no edge here; a near edge needs a cell before it.
  if (!far_edge && (i == 0 || in_zone(i - 1))) return at;
  const std::size_t inner = far_edge ? i : i - 1, outer = inner + 1;
  const double s_in = ve * column_slope(z, length, far_edge ? inner : outer, d);
  const double s_out = ve * column_slope(z, length, far_edge ? outer : inner, d);
  if (!std::isfinite(s_in) || !std::isfinite(s_out)) return at;
  const double bound = s_out >= bounds.upper ? bounds.upper : bounds.lower;
  if (s_out == s_in) return at;
  // Fraction of the way from the zone's cell to the one outside at which the slope crosses.
  const double t = std::clamp((bound - s_in) / (s_out - s_in), 0.0, 0.5);
  return far_edge ? at + t : at - t;
}

StrokeCell stroke_cell(const StrokeContext& ctx, std::size_t p, std::size_t i, bool factual) {
  const std::size_t length = ctx.z.cols();
  const double d = ctx.frame.d;
  const std::size_t row = p - ctx.first_profile;
  const float* zp = ctx.z.row(row);
  StrokeCell c;
  c.cell = {static_cast<std::int32_t>(p), static_cast<std::int32_t>(i)};
  c.z = static_cast<double>(zp[i]);
  double along = static_cast<double>(i);
  if (factual && (ctx.subcell || ctx.drawn)) {
    along = subcell_peak(zp, length, i, d, ctx.view);
  } else if (!factual && ctx.drawn) {
    along = subcell_break(zp, ctx.flags.row(row), length, i, d, ctx.view.ve, ctx.bounds);
  }
  ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), along), c.map.x, c.map.y);
  c.point = c.map;
  // Drawn strokes are smoothed in map geometry; their plan-oblique shift comes after.
  if (ctx.geometry == Geometry::oblique && !ctx.drawn) {
    const double shifted = PlanObliqueShift(ctx.view, d, ctx.z_ref)(along, c.z);
    ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), shifted), c.point.x,
                           c.point.y);
  }
  c.dist = along * d;
  c.offset = along - static_cast<double>(i);
  c.slope_pct = std::fabs(column_slope(zp, length, i, d)) * 100.0;
  c.row_slope_pct = std::fabs(row_slope(ctx.z, row, i, ctx.frame.w)) * 100.0;
  c.depth_m = factual ? hidden_zone(zp, ctx.flags.row(row), length, i, d, ctx.view).depth_m : kNaN;
  return c;
}

double StrokeBuilder::Mean::value() const {
  return count ? sum / count : kNaN;
}

void StrokeBuilder::Sums::add(double slope_pct, double row_slope_pct, double depth_m,
                              double from_front, double height) {
  slope.add(slope_pct);
  row_slope.add(row_slope_pct);
  dist.add(from_front);
  z.add(height);
  // Formulated cells have no hidden zone: their NaN depths count in neither.
  depth.add(depth_m);
  max_depth = std::max(max_depth, depth_m);
}

void StrokeBuilder::add(const StrokeCell& c, bool drawn) {
  if (drawn) {
    drawn_.push_back(
        {c.cell, c.point, {c.dist, c.z, c.offset}, c.slope_pct, c.row_slope_pct, c.depth_m});
    return;
  }
  if (!chain_.empty()) length_ += std::hypot(c.map.x - last_map_.x, c.map.y - last_map_.y);
  last_map_ = c.map;
  sums_.add(c.slope_pct, c.row_slope_pct, c.depth_m, c.dist, c.z);
  chain_.push_back(c.cell);
  points_.push_back(c.point);
}

Stroke StrokeBuilder::stroke(StrokeClass cls) const {
  Stroke s = attributes(cls, cells(), length_, sums_);
  s.chain = chain_;
  s.points = points_;
  return s;
}

Stroke StrokeBuilder::take(StrokeClass cls) {
  Stroke s = attributes(cls, cells(), length_, sums_);
  s.chain = std::move(chain_);
  s.points = std::move(points_);
  clear();
  return s;
}

void StrokeBuilder::drawn_pieces(StrokeClass cls, double max_step,
                                 std::vector<Stroke>& pieces) const {
  const std::size_t n = drawn_.size();
  std::size_t from = 0;
  double length = 0.0;
  for (std::size_t k = 1; k <= n; ++k) {
    const double step = k < n ? distance(drawn_[k - 1].point, drawn_[k].point) : 0.0;
    if (k < n && step <= max_step) {
      length += step;
      continue;
    }
    pieces.push_back(drawn_piece(cls, from, k, length));
    from = k;
    length = 0.0;
  }
}

Stroke StrokeBuilder::drawn_piece(StrokeClass cls, std::size_t from, std::size_t to,
                                  double length) const {
  Sums sums;
  for (std::size_t k = from; k < to; ++k) {
    const DrawnCell& c = drawn_[k];
    sums.add(c.slope_pct, c.row_slope_pct, c.depth_m, c.vertex.dist, c.vertex.z);
  }
  Stroke s = attributes(cls, static_cast<int>(to - from), length, sums);
  // Reserved and appended: sized with resize, each was filled with zeros first.
  s.chain.reserve(to - from);
  s.points.reserve(to - from);
  s.vertices.reserve(to - from);
  for (std::size_t k = from; k < to; ++k) {
    const DrawnCell& c = drawn_[k];
    s.chain.push_back(c.cell);
    s.points.push_back(c.point);
    s.vertices.push_back(c.vertex);
  }
  return s;
}

Stroke StrokeBuilder::attributes(StrokeClass cls, int cells, double length, const Sums& sums) {
  const bool factual = cls == StrokeClass::factual;
  Stroke s;
  s.cls = cls;
  s.cells = cells;
  s.length = length;
  s.mean_slope_pct = sums.slope.value();
  s.mean_row_slope_pct = sums.row_slope.value();
  s.mean_depth_m = factual ? sums.depth.value() : kNaN;
  s.max_depth_m = factual ? sums.max_depth : kNaN;
  s.mean_dist = sums.dist.value();
  s.mean_z = sums.z.value();
  return s;
}

void StrokeBuilder::clear() {
  chain_.clear();
  points_.clear();
  drawn_.clear();
  length_ = 0.0;
  sums_ = Sums();
}

}  // namespace tsk
