#include "strokes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "candidates.h"
#include "slope_filter.h"
#include "visibility.h"

namespace tsk {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean of the finite values added, NaN when there were none.
struct Mean {
  double sum = 0.0;
  int count = 0;
  void add(double v) {
    if (std::isfinite(v)) sum += v, ++count;
  }
  double value() const { return count ? sum / count : kNaN; }
};

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

StrokeCell stroke_cell(const StrokeContext& ctx, std::size_t p, std::size_t i, bool factual) {
  const std::size_t length = ctx.z.cols();
  const double d = ctx.frame.d;
  const std::size_t row = p - ctx.first_profile;
  const float* zp = ctx.z.row(row);
  StrokeCell c;
  c.cell = {static_cast<std::int32_t>(p), static_cast<std::int32_t>(i)};
  c.z = static_cast<double>(zp[i]);
  const double along =
      factual && ctx.subcell ? subcell_peak(zp, length, i, d, ctx.view) : static_cast<double>(i);
  ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), along), c.map.x, c.map.y);
  c.point = c.map;
  if (ctx.geometry == Geometry::oblique) {
    const double shifted = along + ctx.view.ve / (ctx.view.base_slope() * d) * (c.z - ctx.z_ref);
    ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), shifted), c.point.x,
                           c.point.y);
  }
  c.dist = along * d;
  c.slope_pct = std::fabs(column_slope(zp, length, i, d)) * 100.0;
  c.row_slope_pct = std::fabs(row_slope(ctx.z, row, i, ctx.frame.w)) * 100.0;
  c.depth_m = factual ? hidden_zone(zp, ctx.flags.row(row), length, i, d, ctx.view).depth_m : kNaN;
  return c;
}

Stroke stroke_from_cells(const std::vector<StrokeCell>& cells, StrokeClass cls) {
  const bool factual = cls == StrokeClass::factual;
  Stroke s;
  s.cls = cls;
  s.cells = static_cast<int>(cells.size());
  s.chain.reserve(cells.size());
  s.points.reserve(cells.size());
  Mean slope, row, depth, dist, height;
  double max_depth = factual ? 0.0 : kNaN;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const StrokeCell& c = cells[k];
    if (k > 0) s.length += std::hypot(c.map.x - cells[k - 1].map.x, c.map.y - cells[k - 1].map.y);
    s.chain.push_back(c.cell);
    s.points.push_back(c.point);
    slope.add(c.slope_pct);
    row.add(c.row_slope_pct);
    dist.add(c.dist);
    height.add(c.z);
    if (factual) {
      depth.add(c.depth_m);
      max_depth = std::max(max_depth, c.depth_m);
    }
  }
  s.mean_slope_pct = slope.value();
  s.mean_row_slope_pct = row.value();
  s.mean_depth_m = factual ? depth.value() : kNaN;
  s.max_depth_m = max_depth;
  s.mean_dist = dist.value();
  s.mean_z = height.value();
  return s;
}

}  // namespace tsk
