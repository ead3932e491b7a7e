#include "stroke_smoothing.h"

#include <cmath>

namespace tsk {

double polyline_length(const std::vector<StrokePoint>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k)
    length += std::hypot(points[k].x - points[k - 1].x, points[k].y - points[k - 1].y);
  return length;
}

namespace {

struct Smoothed {
  StrokePoint at;
  StrokeVertex vertex;
};

// The Gaussian mean about point k over the points within three sigma of it along the stroke.
Smoothed gaussian_at(const Stroke& stroke, const std::vector<double>& arc, std::size_t k,
                     double sigma) {
  const std::size_t n = stroke.points.size();
  const double reach = 3.0 * sigma, inv = 1.0 / (2.0 * sigma * sigma);
  const bool has_vertices = stroke.vertices.size() == n;
  double sw = 0.0, sx = 0.0, sy = 0.0, sd = 0.0, sz = 0.0;
  std::size_t lo = k;
  while (lo > 0 && arc[k] - arc[lo - 1] <= reach) --lo;
  for (std::size_t j = lo; j < n && arc[j] - arc[k] <= reach; ++j) {
    const double t = arc[j] - arc[k], w = std::exp(-t * t * inv);
    sw += w;
    sx += w * stroke.points[j].x;
    sy += w * stroke.points[j].y;
    if (has_vertices) sd += w * stroke.vertices[j].dist, sz += w * stroke.vertices[j].z;
  }
  return {{sx / sw, sy / sw}, {sd / sw, sz / sw}};
}

}  // namespace

void smooth_stroke(Stroke& stroke, double sigma, double tolerance) {
  const std::size_t n = stroke.points.size();
  if (n < 3 || !(sigma > 0.0)) return;
  std::vector<double> arc(n, 0.0);  // arc length at each point
  for (std::size_t k = 1; k < n; ++k)
    arc[k] = arc[k - 1] + std::hypot(stroke.points[k].x - stroke.points[k - 1].x,
                                     stroke.points[k].y - stroke.points[k - 1].y);
  std::vector<Smoothed> smoothed;
  smoothed.reserve(n);
  for (std::size_t k = 0; k < n; ++k) smoothed.push_back(gaussian_at(stroke, arc, k, sigma));
  const bool has_vertices = stroke.vertices.size() == n;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    StrokePoint& p = stroke.points[k];
    double dx = smoothed[k].at.x - p.x, dy = smoothed[k].at.y - p.y;
    const double moved = std::hypot(dx, dy);
    if (moved > tolerance) dx *= tolerance / moved, dy *= tolerance / moved;
    p.x += dx;
    p.y += dy;
    if (has_vertices) stroke.vertices[k] = smoothed[k].vertex;
  }
}

}  // namespace tsk
