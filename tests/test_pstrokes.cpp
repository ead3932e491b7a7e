// The P-stroke sketch: Visvalingam effective areas against a brute-force oracle, analytic
// shapes, and the combination rule with the f-set.
#include <algorithm>
#include <cmath>
#include <random>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// The oracle: eliminate the smallest remaining triangle (first on ties), one at a time.
std::vector<double> brute_force_areas(const std::vector<double>& x, const std::vector<double>& y) {
  const std::size_t n = x.size();
  std::vector<double> area(n, 0.0);
  std::vector<std::size_t> alive;
  for (std::size_t k = 0; k < n; ++k) alive.push_back(k);
  double floor_area = 0;
  while (alive.size() > 2) {
    std::size_t best = 0;
    double best_area = 1e300, best_signed = 0;
    for (std::size_t j = 1; j + 1 < alive.size(); ++j) {
      const std::size_t a = alive[j - 1], k = alive[j], b = alive[j + 1];
      const double t = 0.5 * ((x[b] - x[a]) * (y[k] - y[a]) - (x[k] - x[a]) * (y[b] - y[a]));
      if (std::fabs(t) < best_area) best = j, best_area = std::fabs(t), best_signed = t;
    }
    floor_area = std::max(floor_area, best_area);
    area[alive[best]] = std::copysign(floor_area, best_signed);
    alive.erase(alive.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return area;
}

}  // namespace

TEST_CASE("effective areas of a peak and a valley", "[pstrokes]") {
  const auto peak = effective_areas({0, 50, 100}, {0, 30, 0});
  CHECK(peak[0] == 0);
  CHECK(peak[1] == Approx(0.5 * 100 * 30));
  CHECK(peak[2] == 0);
  CHECK(effective_areas({0, 50, 100}, {0, -30, 0})[1] == Approx(-1500));
  // A straight line scores nothing; the summit keeps the largest area.
  const auto hill = effective_areas({0, 1, 2, 3, 4}, {0, 1, 2, 1, 0});
  CHECK(hill[1] == 0);
  CHECK(hill[2] == Approx(4.0));
}

TEST_CASE("effective areas agree with the brute-force oracle", "[pstrokes][oracle]") {
  std::mt19937 seeds(99);
  for (int round = 0; round < 200; ++round) {
    const std::uint32_t seed = seeds();
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 100.0);
    const std::size_t n = 3 + rng() % 60;
    std::vector<double> x(n), y(n);
    for (std::size_t k = 0; k < n; ++k) x[k] = 10.0 * k, y[k] = u(rng);
    const auto fast = effective_areas(x, y), slow = brute_force_areas(x, y);
    for (std::size_t k = 0; k < n; ++k) REQUIRE(fast[k] == Approx(slow[k]));
  }
}

TEST_CASE("effective areas of long lines with many equal areas agree with the oracle",
          "[pstrokes][oracle]") {
  // Whole-metre heights on a regular spacing tie often: the first vertex of equal area goes
  // first, in both.
  std::mt19937 rng(20261207);
  for (int round = 0; round < 60; ++round) {
    const std::size_t n = 3 + rng() % 400;
    std::vector<double> x(n), y(n);
    for (std::size_t k = 0; k < n; ++k) x[k] = 30.0 * k, y[k] = static_cast<double>(rng() % 4);
    CAPTURE(round, n);
    CHECK(effective_areas(x, y) == brute_force_areas(x, y));
  }
}

TEST_CASE("a ridge seeds convex column strokes along its crest, drawn across the view",
          "[pstrokes]") {
  // North-south ridge, crest at column 20, seen from the west: the crest is convex along the
  // line of sight (effective area 0.5 * 2000 m * 200 m) and flat across it.
  const HeightGrid dem = make_ridge(30, 41, 50, 200, 0.5);
  SilhouetteParams params;
  const SilhouetteResult r = test::run_on_dem(dem, params, 50, 50);
  const OrientedFrame frame = make_frame(30, 41, 50, 50, 90);
  const auto strokes =
      pstroke_sketch(orient(dem, frame), r.flags, frame, params.view, GeoTransform{}, Geometry::map,
                     PStrokeParams{}, lowest_height(dem));
  int crest = 0;
  for (const PStroke& s : strokes) {
    if (s.seed.i != 20) continue;
    ++crest;
    CHECK(s.cls == PStrokeClass::convex_column);
    CHECK(s.score_m2 >= 15000);
    for (const StrokePoint& pt : s.points) CHECK(pt.x == Approx(20.5));  // across the view
    CHECK(s.points.size() >= 2);
  }
  CHECK(crest == 30);
}

TEST_CASE("no P-stroke is seeded in or extended into the f-set", "[pstrokes]") {
  const HeightGrid dem = test::random_terrain(80, 90, 5);
  SilhouetteParams params;
  const SilhouetteResult r = test::run_on_dem(dem, params, 20, 20);
  const OrientedFrame frame = make_frame(80, 90, 20, 20, 90);
  PStrokeParams tolerances;
  tolerances.convex_column_m2 = tolerances.concave_column_m2 = 500;
  tolerances.convex_row_m2 = tolerances.concave_row_m2 = 500;
  tolerances.half_length = 3;
  const auto strokes =
      pstroke_sketch(orient(dem, frame), r.flags, frame, params.view, GeoTransform{}, Geometry::map,
                     tolerances, lowest_height(dem));
  REQUIRE(strokes.size() > 50);
  for (const PStroke& s : strokes) {
    for (const StrokePoint& pt : s.points) {
      // Identity georeferencing, viewed from the west: x = i + 0.5, y = p + 0.5.
      const auto p = static_cast<std::size_t>(pt.y), i = static_cast<std::size_t>(pt.x);
      REQUIRE_FALSE(r.flags(p, i) & cell::filtered);
      REQUIRE_FALSE(r.flags(p, i) & cell::hidden);
    }
  }
  PStrokeParams bad;
  bad.convex_row_m2 = 0;
  CHECK_THROWS_AS(bad.validate(), Error);
}

TEST_CASE("the P-stroke sketch reports its progress and stops when told", "[pstrokes][interrupt]") {
  // A signal or Cancel after the silhouettes were done used to go unheard until the strokes were
  // all made.
  const HeightGrid dem = test::random_terrain(300, 300, 9);
  SilhouetteParams params;
  const SilhouetteResult r = test::run_on_dem(dem, params, 20, 20);
  const OrientedFrame frame = make_frame(300, 300, 20, 20, 90);
  const HeightGrid oriented = orient(dem, frame);
  std::vector<double> seen;
  const ProgressFn record = [&](double fraction) {
    seen.push_back(fraction);
    return true;
  };
  const auto sketch = [&](const ProgressFn& progress) {
    return pstroke_sketch(oriented, r.flags, frame, params.view, GeoTransform{}, Geometry::map,
                          PStrokeParams{}, lowest_height(dem), 2, progress);
  };
  const std::vector<PStroke> whole = sketch(record);
  REQUIRE(!whole.empty());
  REQUIRE(seen.size() > 10);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() > 0.95);
  for (const double stop_at : {0.1, 0.5, 0.9}) {
    CAPTURE(stop_at);
    CHECK_THROWS_AS(sketch([&](double fraction) { return fraction < stop_at; }), Cancelled);
  }
  CHECK(sketch({}).size() == whole.size());
}
