#include "stroke_smoothing.h"

#include <algorithm>
#include <cmath>

namespace tsk {

double polyline_length(const std::vector<StrokePoint>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double dx = points[k].x - points[k - 1].x, dy = points[k].y - points[k - 1].y;
    length += std::sqrt(dx * dx + dy * dy);
  }
  return length;
}

namespace {

// The Gaussian's weights at 0, 1, 2, ... points away, out to three sigma.
std::vector<double> kernel(double sigma_points, std::size_t n) {
  const std::size_t reach =
      std::min<std::size_t>(n, static_cast<std::size_t>(std::ceil(3.0 * sigma_points)));
  std::vector<double> w(reach + 1);
  for (std::size_t j = 0; j <= reach; ++j)
    w[j] = std::exp(-0.5 * static_cast<double>(j * j) / (sigma_points * sigma_points));
  return w;
}

}  // namespace

void smooth_stroke(Stroke& stroke, double sigma, double tolerance, bool heights) {
  const std::size_t n = stroke.points.size();
  if (n < 3 || !(sigma > 0.0)) return;
  // A chain has a point per profile, so its points lie about evenly along it: the Gaussian over
  // arc length is one over point indices, sigma taken in points at the stroke's mean spacing.
  const double spacing = polyline_length(stroke.points) / static_cast<double>(n - 1);
  if (!(spacing > 0.0)) return;
  const std::vector<double> w = kernel(sigma / spacing, n);
  const auto reach = static_cast<std::ptrdiff_t>(w.size() - 1);
  const bool has_vertices = heights && stroke.vertices.size() == n;
  std::vector<StrokePoint> points(n);
  std::vector<double> z(has_vertices ? n : 0);
  const auto last = static_cast<std::ptrdiff_t>(n - 1);
  for (std::ptrdiff_t k = 1; k < last; ++k) {
    double sw = 0.0, sx = 0.0, sy = 0.0, sz = 0.0;
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, k - reach); j <= std::min(last, k + reach);
         ++j) {
      const double wj = w[static_cast<std::size_t>(std::abs(j - k))];
      const auto u = static_cast<std::size_t>(j);
      sw += wj;
      sx += wj * stroke.points[u].x;
      sy += wj * stroke.points[u].y;
      if (has_vertices) sz += wj * stroke.vertices[u].z;
    }
    const auto u = static_cast<std::size_t>(k);
    points[u] = {sx / sw, sy / sw};
    if (has_vertices) z[u] = sz / sw;
  }
  for (std::size_t k = 1; k + 1 < n; ++k) {
    StrokePoint& p = stroke.points[k];
    double dx = points[k].x - p.x, dy = points[k].y - p.y;
    const double moved = std::sqrt(dx * dx + dy * dy);
    if (moved > tolerance) dx *= tolerance / moved, dy *= tolerance / moved;
    p.x += dx;
    p.y += dy;
    if (has_vertices) stroke.vertices[k].z = z[k];
  }
}

}  // namespace tsk
