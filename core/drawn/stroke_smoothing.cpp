#include "core/drawn/stroke_smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/base/vector_clones.h"

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

// Points summed together by truncated_means: one AVX2 vector of doubles.
constexpr std::ptrdiff_t kLanes = 4;

// The Gaussian's weights from `reach` points before a point to `reach` points after it, out to
// three sigma; the same weights either side, so that a sum over points reads them in turn. Zeros
// lie beyond them for kLanes - 1 points more either side, which truncated_means reads.
struct Kernel {
  std::vector<double> weights;
  std::ptrdiff_t reach = 0;
  double whole_sum = 0.0;  // of the weights, for a point with the whole kernel inside the stroke
  // The weight of a point `j` points after the centre (before it if negative).
  const double* centre() const { return weights.data() + kLanes - 1 + reach; }
  void make(double sigma_points, std::size_t n) {
    reach = static_cast<std::ptrdiff_t>(
        std::min<std::size_t>(n, static_cast<std::size_t>(std::ceil(3.0 * sigma_points))));
    weights.resize(static_cast<std::size_t>(2 * (reach + kLanes - 1) + 1));
    double* w = weights.data() + kLanes - 1 + reach;
    std::fill(w - reach - (kLanes - 1), w - reach, 0.0);
    std::fill(w + reach + 1, w + reach + kLanes, 0.0);
    for (std::ptrdiff_t j = 0; j <= reach; ++j) {
      const auto jj = static_cast<double>(j * j);
      w[j] = w[-j] = std::exp(-0.5 * jj / (sigma_points * sigma_points));
    }
    whole_sum = w[0];
    for (std::ptrdiff_t j = 1; j <= reach; ++j) whole_sum += 2.0 * w[j];
  }
};

// kLanes doubles, one per point summed, in the processor's vector registers (two SSE2 ones in the
// baseline build).
using Lanes = double __attribute__((vector_size(kLanes * sizeof(double))));
static_assert(kLanes == 4, "Lanes are written out as four values");

// The Gaussian means about points [from, to), each over the points its kernel covers, its weights
// renormalised; of heights too if `vertices` are given (into z[k] for point k). Each point's sums
// add its points in order from the first covered. kLanes points are summed at a time, over every
// point any of them covers: a point outside one's kernel has a zero weight there, and adding a
// zero leaves a sum as it was (sums start at +0 and the points are finite), so the sums are those
// of one point at a time, bit for bit.
TSK_VECTOR_CLONES
void truncated_means(const StrokePoint* points, std::ptrdiff_t last, const Kernel& kernel,
                     std::ptrdiff_t from, std::ptrdiff_t to, StrokePoint* out,
                     const StrokeVertex* vertices, double* z) {
  const double* centre = kernel.centre();
  for (std::ptrdiff_t k0 = from; k0 < to; k0 += kLanes) {
    Lanes sw{}, sx{}, sy{}, sz{};
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, k0 - kernel.reach);
    const std::ptrdiff_t hi = std::min(last, k0 + kLanes - 1 + kernel.reach);
    for (std::ptrdiff_t j = lo; j <= hi; ++j) {
      // Point j's weights about points k0 to k0 + kLanes - 1 (the kernel is symmetric).
      Lanes w;
      std::memcpy(&w, centre + (k0 - j), sizeof w);
      const double x = points[j].x, y = points[j].y;
      sw += w;
      sx += w * Lanes{x, x, x, x};
      sy += w * Lanes{y, y, y, y};
      if (vertices) {
        const double h = vertices[j].z;
        sz += w * Lanes{h, h, h, h};
      }
    }
    const Lanes mx = sx / sw, my = sy / sw, mz = sz / sw;
    for (std::ptrdiff_t l = 0; l < kLanes && k0 + l < to; ++l) {
      out[k0 + l] = {mx[l], my[l]};
      if (vertices) z[k0 + l] = mz[l];
    }
  }
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

// Each of `count` smoothed points moved back within `tolerance` of its anchor, into `out`. A loop
// of its own, apart from the heights: the compiler then takes each point's x and y as a pair
// (smoothing on the 4000^2 benchmark: 584 M instructions with the loop inside the pass, 519 M).
// Built for AVX2 too, whose three-operand forms it uses: 103 M instructions here against the
// baseline build's 125 M (and inlined, as it would be without the clones, 278 M).
TSK_VECTOR_CLONES
void hold_within(const StrokePoint* smoothed, const StrokePoint* anchors, double tolerance,
                 std::size_t count, StrokePoint* out) {
  for (std::size_t k = 0; k < count; ++k) {
    double dx = smoothed[k].x - anchors[k].x, dy = smoothed[k].y - anchors[k].y;
    const double moved_squared = dx * dx + dy * dy;
    if (moved_squared > tolerance * tolerance) {
      const double scale = tolerance / std::sqrt(moved_squared);
      dx *= scale, dy *= scale;
    }
    out[k] = {anchors[k].x + dx, anchors[k].y + dy};
  }
}

// One pass: the Gaussian mean about each inner point (of heights too, if `vertices` are given),
// then each point held within `tolerance` of its anchor.
void smoothing_pass(std::vector<StrokePoint>& points, const Kernel& kernel,
                    const std::vector<StrokePoint>& anchors, double tolerance,
                    std::vector<StrokePoint>& scratch, std::vector<double>& z,
                    std::vector<StrokeVertex>* vertices) {
  const auto last = static_cast<std::ptrdiff_t>(points.size() - 1);
  const std::ptrdiff_t reach = kernel.reach;
  scratch.resize(points.size());  // every inner point is written; the ends stay
  scratch.front() = points.front();
  scratch.back() = points.back();
  z.resize(vertices ? points.size() : 0);
  const StrokeVertex* heights = vertices ? vertices->data() : nullptr;
  // Points [whole_from, whole_to) have the whole kernel inside the stroke (heights are smoothed
  // point by point).
  const std::ptrdiff_t whole_from = vertices ? last : std::clamp<std::ptrdiff_t>(reach, 1, last);
  const std::ptrdiff_t whole_to = std::max(whole_from, last - reach + 1);
  truncated_means(points.data(), last, kernel, 1, whole_from, scratch.data(), heights, z.data());
  if (whole_from < whole_to) {
    whole_kernel_means(points.data(), kernel.centre(), static_cast<std::size_t>(reach + 1),
                       kernel.whole_sum, static_cast<std::size_t>(whole_from),
                       static_cast<std::size_t>(whole_to), scratch.data());
  }
  truncated_means(points.data(), last, kernel, whole_to, last, scratch.data(), heights, z.data());
  hold_within(scratch.data(), anchors.data(), tolerance, points.size(), points.data());
  if (vertices) {
    for (std::size_t k = 1; k + 1 < points.size(); ++k) (*vertices)[k].z = z[k];
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
  thread_local Kernel kernel;
  kernel.make(sigma / spacing, n);
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
    smoothing_pass(stroke.points, kernel, held, tolerance, scratch, z,
                   first && heights && stroke.vertices.size() == n ? &stroke.vertices : nullptr);
  }
}

}  // namespace tsk
