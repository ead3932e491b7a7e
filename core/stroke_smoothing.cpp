#include "stroke_smoothing.h"

#include <algorithm>
#include <cmath>

#include "vector_clones.h"

namespace tsk {

constexpr int kSmoothingPasses = 3;

double polyline_length(const std::vector<StrokePoint>& points) {
  double length = 0.0;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const double dx = points[k].x - points[k - 1].x, dy = points[k].y - points[k - 1].y;
    length += std::sqrt(dx * dx + dy * dy);
  }
  return length;
}

namespace {

// The Gaussian's weights at 0, 1, 2, ... points away, out to three sigma, into `w`.
void kernel(double sigma_points, std::size_t n, std::vector<double>& w) {
  const std::size_t reach =
      std::min<std::size_t>(n, static_cast<std::size_t>(std::ceil(3.0 * sigma_points)));
  w.resize(reach + 1);
  for (std::size_t j = 0; j <= reach; ++j)
    w[j] = std::exp(-0.5 * static_cast<double>(j * j) / (sigma_points * sigma_points));
}

// The Gaussian mean about point k where the kernel runs past an end of the stroke: the weights
// of the points it covers, renormalised; of heights too if `z` is given. (Summed in order from the
// first point covered, the left side's weights read backwards: no branch per point.)
template <bool kHeights>
StrokePoint truncated_mean(const std::vector<StrokePoint>& points, const std::vector<double>& w,
                           std::ptrdiff_t k, std::ptrdiff_t last,
                           const std::vector<StrokeVertex>* vertices, double* z) {
  const auto reach = static_cast<std::ptrdiff_t>(w.size() - 1);
  const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, k - reach), hi = std::min(last, k + reach);
  double sw = 0.0, sx = 0.0, sy = 0.0, sz = 0.0;
  const auto add = [&](std::ptrdiff_t j, double wj) {
    const auto v = static_cast<std::size_t>(j);
    sw += wj;
    sx += wj * points[v].x;
    sy += wj * points[v].y;
    if constexpr (kHeights) sz += wj * (*vertices)[v].z;
  };
  for (std::ptrdiff_t j = lo; j < k; ++j) add(j, w[static_cast<std::size_t>(k - j)]);
  for (std::ptrdiff_t j = k; j <= hi; ++j) add(j, w[static_cast<std::size_t>(j - k)]);
  if constexpr (kHeights) *z = sz / sw;
  return {sx / sw, sy / sw};
}

// The Gaussian means about points [from, to), where the kernel lies whole inside the stroke:
// pairs of points either side, one normaliser. Taps outermost, so that the loops run along the
// points and vectorise; each point's sum still adds its pairs in order from the nearest.
TSK_VECTOR_CLONES
void whole_kernel_means(const StrokePoint* points, const double* w, std::size_t taps, double total,
                        std::size_t from, std::size_t to, StrokePoint* out) {
  for (std::size_t k = from; k < to; ++k) out[k] = {w[0] * points[k].x, w[0] * points[k].y};
  for (std::size_t j = 1; j < taps; ++j) {
    const double wj = w[j];
    for (std::size_t k = from; k < to; ++k) {
      out[k].x += wj * (points[k - j].x + points[k + j].x);
      out[k].y += wj * (points[k - j].y + points[k + j].y);
    }
  }
  for (std::size_t k = from; k < to; ++k) out[k] = {out[k].x / total, out[k].y / total};
}

// One pass: the Gaussian mean about each inner point (of heights too, if `vertices` are given),
// then each point held within `tolerance` of its anchor.
void smoothing_pass(std::vector<StrokePoint>& points, const std::vector<double>& w,
                    const std::vector<StrokePoint>& anchors, double tolerance,
                    std::vector<StrokePoint>& scratch, std::vector<double>& z,
                    std::vector<StrokeVertex>* vertices) {
  const auto last = static_cast<std::ptrdiff_t>(points.size() - 1);
  const auto reach = static_cast<std::ptrdiff_t>(w.size() - 1);
  scratch.resize(points.size());  // every inner point is written; the ends stay
  scratch.front() = points.front();
  scratch.back() = points.back();
  z.resize(vertices ? points.size() : 0);
  const auto near_an_end = [&](std::ptrdiff_t k) {
    const auto u = static_cast<std::size_t>(k);
    scratch[u] = vertices ? truncated_mean<true>(points, w, k, last, vertices, &z[u])
                          : truncated_mean<false>(points, w, k, last, nullptr, nullptr);
  };
  // Points [whole_from, whole_to) have the whole kernel inside the stroke (heights are smoothed
  // point by point).
  const std::ptrdiff_t whole_from = vertices ? last : std::clamp<std::ptrdiff_t>(reach, 1, last);
  const std::ptrdiff_t whole_to = std::max(whole_from, last - reach + 1);
  for (std::ptrdiff_t k = 1; k < whole_from; ++k) near_an_end(k);
  if (whole_from < whole_to) {
    double total = w[0];
    for (std::size_t j = 1; j < w.size(); ++j) total += 2.0 * w[j];
    whole_kernel_means(points.data(), w.data(), w.size(), total,
                       static_cast<std::size_t>(whole_from), static_cast<std::size_t>(whole_to),
                       scratch.data());
  }
  for (std::ptrdiff_t k = whole_to; k < last; ++k) near_an_end(k);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const StrokePoint anchor = anchors[k];
    double dx = scratch[k].x - anchor.x, dy = scratch[k].y - anchor.y;
    const double moved_squared = dx * dx + dy * dy;
    if (moved_squared > tolerance * tolerance) {
      const double scale = tolerance / std::sqrt(moved_squared);
      dx *= scale, dy *= scale;
    }
    points[k] = {anchor.x + dx, anchor.y + dy};
    if (vertices && k > 0 && static_cast<std::ptrdiff_t>(k) < last) (*vertices)[k].z = z[k];
  }
}

}  // namespace

void smooth_stroke(Stroke& stroke, double sigma, double tolerance, bool heights,
                   const std::vector<StrokePoint>* anchors) {
  const std::size_t n = stroke.points.size();
  if (n < 3 || !(sigma > 0.0)) return;
  // A chain has a point per profile, so its points lie about evenly along it: the Gaussian over
  // arc length is one over point indices, sigma taken in points at the stroke's mean spacing.
  const double spacing = polyline_length(stroke.points) / static_cast<double>(n - 1);
  if (!(spacing > 0.0)) return;
  // Storage kept from stroke to stroke (smoothing runs on one thread at a time per drawer).
  thread_local std::vector<double> w;
  kernel(sigma / spacing, n, w);
  // Points are held near their anchors, or near where they were when no anchors are given.
  std::vector<StrokePoint> where_they_were;
  if (!anchors || anchors->size() != n) where_they_were = stroke.points;
  const std::vector<StrokePoint>& held = where_they_were.empty() ? *anchors : where_they_were;
  thread_local std::vector<StrokePoint> scratch;
  thread_local std::vector<double> z;
  // Where a pass pulls a point back within the tolerance, it leaves a kink; the next passes
  // smooth the kinks out within the same band.
  for (int pass = 0; pass < kSmoothingPasses; ++pass) {
    const bool first = pass == 0;
    smoothing_pass(stroke.points, w, held, tolerance, scratch, z,
                   first && heights && stroke.vertices.size() == n ? &stroke.vertices : nullptr);
  }
}

}  // namespace tsk
