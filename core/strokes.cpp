#include "strokes.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "candidates.h"
#include "parallel.h"
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

namespace {

// The stroke of one chain, with its points in the chosen geometry and its attributes.
Stroke make_stroke(const Chain& chain, StrokeClass cls, const StrokeContext& ctx) {
  const std::size_t length = ctx.z.cols();
  const double d = ctx.frame.d;
  const double oblique_cells_per_metre = ctx.view.ve / (ctx.view.base_slope() * d);
  const bool factual = cls == StrokeClass::factual;
  Stroke s;
  s.cls = cls;
  s.cells = static_cast<int>(chain.size());
  s.chain = chain;
  s.points.reserve(chain.size());
  Mean slope, row, depth, dist, height;
  double max_depth = factual ? 0.0 : kNaN;
  double prev_x = 0.0, prev_y = 0.0;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    const auto p = static_cast<std::size_t>(chain[k].p);
    const auto i = static_cast<std::size_t>(chain[k].i);
    const float* zp = ctx.z.row(p);
    const double zi = static_cast<double>(zp[i]);
    const double along =
        factual && ctx.subcell ? subcell_peak(zp, length, i, d, ctx.view) : static_cast<double>(i);
    double map_x, map_y;
    ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), along), map_x, map_y);
    if (k > 0) s.length += std::hypot(map_x - prev_x, map_y - prev_y);
    prev_x = map_x, prev_y = map_y;
    StrokePoint pt{map_x, map_y};
    if (ctx.geometry == Geometry::oblique) {
      const double shifted = along + oblique_cells_per_metre * (zi - ctx.z_ref);
      ctx.geotransform.apply(ctx.frame.to_pixel(static_cast<double>(p), shifted), pt.x, pt.y);
    }
    s.points.push_back(pt);
    slope.add(std::fabs(column_slope(zp, length, i, d)) * 100.0);
    row.add(std::fabs(row_slope(ctx.z, p, i, ctx.frame.w)) * 100.0);
    dist.add(along * d);
    height.add(zi);
    if (factual) {
      const HiddenZone zone = hidden_zone(zp, ctx.flags.row(p), length, i, d, ctx.view);
      depth.add(zone.depth_m);
      max_depth = std::max(max_depth, zone.depth_m);
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

}  // namespace

void make_strokes(const std::vector<Chain>& chains, StrokeClass cls, int min_cells,
                  const StrokeContext& ctx, std::vector<Stroke>& out, unsigned threads) {
  std::vector<const Chain*> kept;
  for (const Chain& chain : chains) {
    if (static_cast<int>(chain.size()) >= min_cells) kept.push_back(&chain);
  }
  const std::size_t first = out.size();
  out.resize(first + kept.size());
  // Strokes are independent: build them on every thread, in chain order.
  parallel_for(kept.size(), threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) out[first + k] = make_stroke(*kept[k], cls, ctx);
  });
}

}  // namespace tsk
