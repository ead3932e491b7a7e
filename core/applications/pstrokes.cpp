#include "core/applications/pstrokes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include "core/base/errors.h"
#include "core/base/parallel.h"
#include "core/method/plan_oblique.h"

namespace tsk {

void PStrokeParams::validate() const {
  for (double t : {convex_column_m2, concave_column_m2, convex_row_m2, concave_row_m2}) {
    if (!std::isfinite(t) || t <= 0) throw Error("P-stroke tolerances must be positive areas (m2)");
  }
  if (half_length < 1 || half_length > 100) throw Error("P-stroke half length must be 1 to 100");
}

const char* pstroke_class_name(PStrokeClass c) {
  static const char* const names[] = {"convex_column", "concave_column", "convex_row",
                                      "concave_row"};
  return names[static_cast<int>(c)];
}

namespace {

// The interior vertices of a line still to remove, least effective area first (ties: the first
// vertex), each found by its place in the heap so that a neighbour's new area moves it there
// rather than adding an entry: a line of n vertices keeps n entries, not 3n to sift through.
// Four children a node, each entry with its key: half the levels, and the keys compared side by
// side in the cache rather than looked up.
class VertexHeap {
 public:
  // Holds vertices 1 to n - 2 of a line of n, keyed by their areas' magnitudes.
  explicit VertexHeap(const std::vector<double>& areas) : place_(areas.size()) {
    const std::size_t n = areas.size();
    for (std::size_t k = 1; k + 1 < n; ++k) {
      place_[k] = static_cast<std::uint32_t>(heap_.size());
      heap_.push_back({std::fabs(areas[k]), static_cast<std::uint32_t>(k)});
    }
    for (std::size_t at = heap_.size(); at-- > 0;) sift_down(at);  // leaves stay put
  }
  bool empty() const { return heap_.empty(); }
  // Takes the vertex of least key.
  std::size_t pop() {
    const std::uint32_t top = heap_.front().vertex;
    const Entry last = heap_.back();
    heap_.pop_back();
    if (!heap_.empty()) {
      heap_.front() = last;
      sift_down(0);
    }
    return top;
  }
  // Gives vertex k (still held) its new key, and moves it where that belongs.
  void update(std::size_t k, double key) {
    const std::size_t at = place_[k];
    const bool smaller = key < heap_[at].key;
    heap_[at].key = key;
    if (smaller) {
      sift_up(at);
    } else {
      sift_down(at);
    }
  }

 private:
  static constexpr std::size_t kArity = 4;
  struct Entry {
    double key;
    std::uint32_t vertex;
    bool operator<(const Entry& o) const {
      return key < o.key || (key == o.key && vertex < o.vertex);
    }
  };
  void put(const Entry& e, std::size_t at) {
    heap_[at] = e;
    place_[e.vertex] = static_cast<std::uint32_t>(at);
  }
  void sift_up(std::size_t at) {
    const Entry e = heap_[at];
    while (at > 0 && e < heap_[(at - 1) / kArity]) {
      put(heap_[(at - 1) / kArity], at);
      at = (at - 1) / kArity;
    }
    put(e, at);
  }
  void sift_down(std::size_t at) {
    const Entry e = heap_[at];
    const std::size_t n = heap_.size();
    for (;;) {
      const std::size_t first = kArity * at + 1;
      if (first >= n) break;
      std::size_t least = first;
      const std::size_t end = std::min(first + kArity, n);
      for (std::size_t c = first + 1; c < end; ++c) least = heap_[c] < heap_[least] ? c : least;
      if (!(heap_[least] < e)) break;
      put(heap_[least], at);
      at = least;
    }
    put(e, at);
  }

  std::vector<Entry> heap_;
  std::vector<std::uint32_t> place_;
};

}  // namespace

std::vector<double> effective_areas(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> area(n, 0.0);
  if (n < 3) return area;
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t k = 0; k < n; ++k) prev[k] = k - 1, next[k] = k + 1;
  // Signed triangle area: positive when vertex k lies above the chord from a to b.
  auto triangle = [&](std::size_t a, std::size_t k, std::size_t b) {
    return 0.5 * ((x[b] - x[a]) * (y[k] - y[a]) - (x[k] - x[a]) * (y[b] - y[a]));
  };
  std::vector<double> current(n, 0.0);
  for (std::size_t k = 1; k + 1 < n; ++k) current[k] = triangle(k - 1, k, k + 1);
  VertexHeap heap(current);
  double floor_area = 0.0;
  while (!heap.empty()) {
    const std::size_t k = heap.pop();
    floor_area = std::max(floor_area, std::fabs(current[k]));
    area[k] = std::copysign(floor_area, current[k]);
    next[prev[k]] = next[k];
    prev[next[k]] = prev[k];
    for (std::size_t j : {prev[k], next[k]}) {
      if (j == 0 || j + 1 == n) continue;
      current[j] = triangle(prev[j], j, next[j]);
      heap.update(j, std::fabs(current[j]));
    }
  }
  return area;
}

namespace {

// Scores runs of valid cells of one line; `at(k)` gives the grid cell of position k.
template <typename At>
void score_line(std::size_t count, double spacing, const HeightGrid& z, At at,
                std::vector<float>& scores) {
  std::vector<double> xs, ys;
  std::vector<std::size_t> cells;
  auto flush = [&] {
    const std::vector<double> areas = effective_areas(xs, ys);
    for (std::size_t k = 0; k < cells.size(); ++k) scores[cells[k]] = static_cast<float>(areas[k]);
    xs.clear(), ys.clear(), cells.clear();
  };
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t c = at(k);
    const float h = z.data()[c];
    if (!is_data(h)) {
      flush();
      continue;
    }
    xs.push_back(static_cast<double>(k) * spacing);
    ys.push_back(static_cast<double>(h));
    cells.push_back(c);
  }
  flush();
}

}  // namespace

std::vector<PStroke> pstroke_sketch(const HeightGrid& z, const CellFlags& flags,
                                    const OrientedFrame& frame, const ViewParams& view,
                                    const GeoTransform& geotransform, Geometry geometry,
                                    const PStrokeParams& params, double z_ref, unsigned threads,
                                    const ProgressFn& progress) {
  params.validate();
  const std::size_t P = frame.profiles, L = frame.length;
  std::vector<float> column(z.size(), 0.f), row(z.size(), 0.f);
  parallel_for(
      P, threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
          score_line(
              L, frame.d, z, [&](std::size_t i) { return p * L + i; }, column);
      },
      progress_part(progress, 0.0, 0.4));
  parallel_for(
      L, threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i)
          score_line(
              P, frame.w, z, [&](std::size_t p) { return p * L + i; }, row);
      },
      progress_part(progress, 0.4, 0.8));
  const PlanObliqueShift shift(view, frame.d, z_ref);
  auto drawable = [&](std::size_t p, std::size_t i) {
    const std::uint8_t f = flags(p, i);
    return (f & cell::valid) && !(f & cell::hidden) && !(f & cell::filtered);
  };
  auto point = [&](std::size_t p, std::size_t i) {
    const double s = geometry == Geometry::oblique
                         ? shift(static_cast<double>(i), static_cast<double>(z(p, i)))
                         : static_cast<double>(i);
    StrokePoint pt{};
    geotransform.apply(frame.to_pixel(static_cast<double>(p), s), pt.x, pt.y);
    return pt;
  };
  std::vector<PStroke> strokes;
  for (std::size_t p = 0; p < P; ++p) {
    tell_progress(progress, 0.8 + 0.2 * static_cast<double>(p) / static_cast<double>(P));
    for (std::size_t i = 0; i < L; ++i) {
      if (!drawable(p, i)) continue;
      const double c = column[p * L + i], r = row[p * L + i];
      // The strongest class relative to its tolerance seeds the stroke.
      const struct {
        PStrokeClass cls;
        double score, tolerance;
      } options[] = {{PStrokeClass::convex_column, c, params.convex_column_m2},
                     {PStrokeClass::concave_column, -c, params.concave_column_m2},
                     {PStrokeClass::convex_row, r, params.convex_row_m2},
                     {PStrokeClass::concave_row, -r, params.concave_row_m2}};
      int best = -1;
      double best_ratio = 1.0;
      for (int k = 0; k < 4; ++k) {
        const double ratio = options[k].score / options[k].tolerance;
        if (ratio >= best_ratio) best = k, best_ratio = ratio;
      }
      if (best < 0) continue;
      // Along the cross-section, stopping before hidden, nodata or f-set cells.
      std::size_t lo = p, hi = p;
      for (int k = 0; k < params.half_length && lo > 0 && drawable(lo - 1, i); ++k) --lo;
      for (int k = 0; k < params.half_length && hi + 1 < P && drawable(hi + 1, i); ++k) ++hi;
      if (lo == hi) continue;
      PStroke s{options[best].cls,
                options[best].score,
                {static_cast<std::int32_t>(p), static_cast<std::int32_t>(i)},
                {}};
      for (std::size_t q = lo; q <= hi; ++q) s.points.push_back(point(q, i));
      strokes.push_back(std::move(s));
    }
  }
  return strokes;
}

}  // namespace tsk
