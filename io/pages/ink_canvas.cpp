#include "io/pages/ink_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace tsk::io {
namespace {

// A long segment is inked in pieces this many pixels long at most, so that the box of pixels
// looked at around each piece holds few beyond its reach (a diagonal's box is a square).
constexpr double kPiecePixels = 8.0;

// The first and last pixel index within [lo, hi] on an axis of `size` pixels, clamped before
// any conversion to int (a coordinate far off the canvas does not fit one).
bool pixel_span(double lo, double hi, int size, int& first, int& last) {
  lo = std::max(lo, 0.0);
  hi = std::min(hi, static_cast<double>(size) - 1.0);
  if (!(lo <= hi)) return false;
  first = static_cast<int>(std::floor(lo));
  last = static_cast<int>(std::ceil(hi));
  return true;
}

// Narrows [t0, t1] to the t where p * t <= q (one side of a box, Liang and Barsky's clipping);
// false when nothing is left.
bool clip_span(double p, double q, double& t0, double& t1) {
  if (p == 0.0) return q >= 0.0;
  const double t = q / p;
  if (p < 0.0) {
    t0 = std::max(t0, t);
  } else {
    t1 = std::min(t1, t);
  }
  return t0 <= t1;
}

}  // namespace

InkCanvas::InkCanvas(int width, int height)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      ink_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0.f) {}

void InkCanvas::line(double x0, double y0, double x1, double y1, double radius, float darkness) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
      !std::isfinite(radius) || radius < 0.0) {
    return;
  }
  // Only the part of the segment within reach of the canvas can ink it: clipped first, a segment
  // far longer than the canvas is not cut into pieces that all miss it.
  // The canvas grown by more than the ink's reach (radius + 0.5) on every side.
  const double margin = radius + 1.0;
  const double dx = x1 - x0, dy = y1 - y0;
  double t0 = 0.0, t1 = 1.0;
  if (!clip_span(-dx, x0 + margin, t0, t1) || !clip_span(dx, width_ + margin - x0, t0, t1) ||
      !clip_span(-dy, y0 + margin, t0, t1) || !clip_span(dy, height_ + margin - y0, t0, t1)) {
    return;
  }
  const double ax = x0 + t0 * dx, ay = y0 + t0 * dy;
  const double cx = (t1 - t0) * dx, cy = (t1 - t0) * dy;
  const int pieces =
      static_cast<int>(std::max(1.0, std::ceil(std::sqrt(cx * cx + cy * cy) / kPiecePixels)));
  for (int k = 0; k < pieces; ++k) {
    const double from = static_cast<double>(k) / pieces, to = static_cast<double>(k + 1) / pieces;
    capsule(ax + from * cx, ay + from * cy, ax + to * cx, ay + to * cy, radius, darkness);
  }
}

void InkCanvas::capsule(double ax, double ay, double bx, double by, double radius, float darkness) {
  const double reach = radius + 0.5;  // coverage is 0 from here on
  int x_first, x_last, y_first, y_last;
  if (!pixel_span(std::min(ax, bx) - reach - 0.5, std::max(ax, bx) + reach - 0.5, width_, x_first,
                  x_last) ||
      !pixel_span(std::min(ay, by) - reach - 0.5, std::max(ay, by) + reach - 0.5, height_, y_first,
                  y_last)) {
    return;
  }
  const double dx = bx - ax, dy = by - ay;
  const double length2 = dx * dx + dy * dy;
  const double inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
  const double reach2 = reach * reach;
  for (int y = y_first; y <= y_last; ++y) {
    const double py = y + 0.5 - ay;
    float* row = ink_.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(width_);
    for (int x = x_first; x <= x_last; ++x) {
      const double px = x + 0.5 - ax;
      // The nearest point of the segment to the pixel's centre, at t along it.
      const double t = std::clamp((px * dx + py * dy) * inverse, 0.0, 1.0);
      const double ex = px - t * dx, ey = py - t * dy;
      const double distance2 = ex * ex + ey * ey;
      if (distance2 >= reach2) continue;
      const double coverage = std::min(1.0, reach - std::sqrt(distance2));
      row[x] = std::max(row[x], static_cast<float>(coverage) * darkness);
    }
  }
}

std::vector<std::uint8_t> InkCanvas::pixels() const {
  std::vector<std::uint8_t> out(ink_.size());
  for (std::size_t k = 0; k < ink_.size(); ++k) {
    out[k] = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - std::min(1.f, ink_[k]))));
  }
  return out;
}

}  // namespace tsk::io
