// Geometry of the vector previews: tapered outlines and the plotter's order.
#include <algorithm>
#include <cmath>
#include <random>

#include "catch_compat.h"
#include "core/drawn/pen_plot.h"
#include "core/drawn/stroke_outline.h"

using namespace tsk;

namespace {

// Area of a closed ring (shoelace).
double ring_area(const std::vector<StrokePoint>& ring) {
  double twice = 0.0;
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const StrokePoint a = ring[k], b = ring[(k + 1) % ring.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return std::fabs(twice) / 2.0;
}

}  // namespace

TEST_CASE("a tapered outline lies half its width either side of the line", "[preview][outline]") {
  const std::vector<StrokePoint> line = {{0, 0}, {10, 0}, {20, 0}};
  const std::vector<StrokePoint> ring = tapered_outline(line, {0.0, 2.0, 0.0});
  // Tip, left side (y > 0 for a line running +x), tip, right side backwards.
  REQUIRE(ring.size() == 8);
  CHECK(ring[2].y == Approx(1.0));
  CHECK(ring[6].y == Approx(-1.0));
  CHECK(ring[2].x == Approx(10.0));
  // Two triangles of base 20 and height 1 each side: the outline's area is the width's integral.
  CHECK(ring_area(ring) == Approx(20.0));
  // At a right-angle turn the sides stay parallel to the line: the corner lies on the bisector.
  const std::vector<StrokePoint> corner = tapered_outline({{0, 0}, {10, 0}, {10, 10}}, {2, 2, 2});
  CHECK(corner[2].x == Approx(10.0 - 1.0));
  CHECK(corner[2].y == Approx(1.0));
  CHECK(tapered_outline({{0, 0}}, {1.0}).empty());
}

TEST_CASE("the plotter merges paths that meet, keeps every point and cuts the travel",
          "[preview][plotter]") {
  // Two paths meeting end to start, one meeting them reversed, one apart.
  const std::vector<std::vector<StrokePoint>> meeting = {
      {{0, 0}, {1, 0}}, {{1, 0}, {2, 0}}, {{3, 0}, {2, 0}}, {{0, 5}, {1, 5}}};
  const PenPlan merged = plan_pen_paths(meeting, 0.01, {0, 0});
  CHECK(merged.paths.size() == 2);
  std::size_t points = 0;
  for (const auto& p : merged.paths) points += p.size();
  CHECK(points == 8);

  // Random short dashes over a square: ordering them nearest first cuts the pen-up travel to a
  // fraction of drawing them as given, and every dash is drawn once, whole.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1000.0);
  std::vector<std::vector<StrokePoint>> dashes;
  for (int k = 0; k < 3000; ++k) {
    const StrokePoint a{u(rng), u(rng)};
    dashes.push_back({a, {a.x + 3.0, a.y + 1.0}});
  }
  const PenPlan plan = plan_pen_paths(dashes, 0.0, {0, 0});
  REQUIRE(plan.paths.size() == dashes.size());
  CHECK(plan.travel_before == Approx(pen_up_travel(dashes, {0, 0})));
  CHECK(plan.travel_after == Approx(pen_up_travel(plan.paths, {0, 0})));
  CHECK(plan.travel_after * 10.0 < plan.travel_before);
  auto key = [](const std::vector<StrokePoint>& p) {
    const StrokePoint a =
        std::min(p.front(), p.back(), [](StrokePoint l, StrokePoint r) { return l.x < r.x; });
    return std::make_pair(a.x, a.y);
  };
  std::vector<std::pair<double, double>> given, drawn;
  for (const auto& p : dashes) given.push_back(key(p));
  for (const auto& p : plan.paths) drawn.push_back(key(p));
  std::sort(given.begin(), given.end());
  std::sort(drawn.begin(), drawn.end());
  CHECK(given == drawn);
}
