#include "core/drawn/stroke_outline.h"

#include <algorithm>
#include <cmath>

namespace tsk {
namespace {

struct Direction {
  double x = 0.0, y = 0.0;
};

Direction unit(StrokePoint from, StrokePoint to) {
  const double dx = to.x - from.x, dy = to.y - from.y, len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0) return {};
  return {dx / len, dy / len};
}

}  // namespace

std::vector<StrokePoint> tapered_outline(const std::vector<StrokePoint>& line,
                                         const std::vector<double>& widths) {
  const std::size_t n = line.size();
  if (n < 2 || widths.size() != n) return {};
  // The direction along the line at each point: of the segment before and after it, averaged.
  std::vector<Direction> along(n);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Direction d = unit(line[k], line[k + 1]);
    along[k].x += d.x, along[k].y += d.y;
    along[k + 1].x += d.x, along[k + 1].y += d.y;
  }
  std::vector<StrokePoint> left, right;
  left.reserve(n);
  right.reserve(n);
  Direction last_seen{1.0, 0.0};
  for (std::size_t k = 0; k < n; ++k) {
    const double len = std::sqrt(along[k].x * along[k].x + along[k].y * along[k].y);
    Direction t = len > 1e-12 ? Direction{along[k].x / len, along[k].y / len} : last_seen;
    last_seen = t;
    // The mean direction's normal, lengthened at a turn to keep the sides parallel (a miter),
    // but never beyond twice the half width.
    const Direction in = k > 0 ? unit(line[k - 1], line[k]) : t;
    const double cos_half = std::max(0.5, std::fabs(in.x * t.x + in.y * t.y));
    const double half = 0.5 * widths[k] / cos_half;
    left.push_back({line[k].x - t.y * half, line[k].y + t.x * half});
    right.push_back({line[k].x + t.y * half, line[k].y - t.x * half});
  }
  const Direction first = unit(line[1], line[0]), end = unit(line[n - 2], line[n - 1]);
  std::vector<StrokePoint> outline;
  outline.reserve(2 * n + 2);
  outline.push_back({line[0].x + first.x * 0.5 * widths[0], line[0].y + first.y * 0.5 * widths[0]});
  for (const StrokePoint& q : left) outline.push_back(q);
  outline.push_back(
      {line[n - 1].x + end.x * 0.5 * widths[n - 1], line[n - 1].y + end.y * 0.5 * widths[n - 1]});
  for (auto it = right.rbegin(); it != right.rend(); ++it) outline.push_back(*it);
  return outline;
}

}  // namespace tsk
