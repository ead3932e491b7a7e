// Drawn strokes (issue 15): joining, generalisation after joining, smoothing within a tolerance,
// weights, and the exact mode's statistics left alone.
#include <algorithm>
#include <cmath>
#include <random>

#include "catch_compat.h"
#include "core/drawn/drawing_pipeline.h"
#include "core/drawn/drawn_strokes.h"
#include "core/drawn/stroke_joining.h"
#include "core/drawn/stroke_smoothing.h"
#include "core/drawn/stroke_weights.h"
#include "core/method/orient.h"
#include "core/method/plan_oblique.h"
#include "support/analytic_terrain.h"
#include "test_support.h"

using namespace tsk;

namespace {

Stroke line_stroke(std::vector<StrokePoint> points, StrokeClass cls = StrokeClass::factual) {
  Stroke s;
  s.cls = cls;
  s.points = std::move(points);
  s.cells = static_cast<int>(s.points.size());
  s.length = polyline_length(s.points);
  return s;
}

// A straight stroke from (x0, y) to (x1, y), a point per unit.
Stroke row_stroke(int x0, int x1, double y) {
  std::vector<StrokePoint> pts;
  for (int x = x0; x <= x1; ++x) pts.push_back({static_cast<double>(x), y});
  return line_stroke(pts);
}

// Total absolute turning angle over total length (radians per unit).
double turning_per_length(const std::vector<StrokePoint>& p) {
  double turn = 0.0;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const double a = std::atan2(p[k].y - p[k - 1].y, p[k].x - p[k - 1].x);
    const double b = std::atan2(p[k + 1].y - p[k].y, p[k + 1].x - p[k].x);
    turn += std::fabs(std::remainder(b - a, 2.0 * 3.14159265358979323846));
  }
  return turn / polyline_length(p);
}

const JoinRule kRule{2.5, 35.0};

}  // namespace

TEST_CASE("a ridge broken by one-cell gaps is joined into one stroke", "[drawn][joining]") {
  // Four pieces along y = 0 with one missing cell between them, given out of order and one
  // reversed, as chains of a scan may come.
  std::vector<Stroke> pieces = {row_stroke(6, 10, 0), row_stroke(0, 4, 0), row_stroke(18, 22, 0),
                                row_stroke(12, 16, 0)};
  std::reverse(pieces[2].points.begin(), pieces[2].points.end());
  const std::vector<Stroke> joined = join_strokes(pieces, kRule);
  REQUIRE(joined.size() == 1);
  CHECK(joined[0].cells == 20);
  REQUIRE(joined[0].points.size() == 20);
  // Its points run monotonically from one end to the other.
  const double step = joined[0].points[1].x - joined[0].points[0].x;
  for (std::size_t k = 1; k < joined[0].points.size(); ++k)
    CHECK((joined[0].points[k].x - joined[0].points[k - 1].x) * step > 0.0);
  CHECK(joined[0].length == Approx(4 * 4.0 + 3 * 2.0));
}

TEST_CASE("two short parallel strokes apart stay two", "[drawn][joining]") {
  CHECK(join_strokes({row_stroke(0, 3, 0), row_stroke(0, 3, 10)}, kRule).size() == 2);
  // Side by side one cell apart they are still not one line: each end leads nowhere near the
  // other's start.
  CHECK(join_strokes({row_stroke(0, 3, 0), row_stroke(0, 3, 1)}, kRule).size() == 2);
}

TEST_CASE("a T-junction is not joined across", "[drawn][joining]") {
  // A stroke ending at the middle of another.
  const Stroke bar = row_stroke(0, 10, 0);
  Stroke stem = line_stroke({{5, 1}, {5, 2}, {5, 3}, {5, 4}, {5, 5}});
  CHECK(join_strokes({bar, stem}, kRule).size() == 2);
  // A stroke turning off at a right angle just past another's end.
  stem = line_stroke({{11, 1}, {11, 2}, {11, 3}, {11, 4}});
  CHECK(join_strokes({bar, stem}, kRule).size() == 2);
  // Straight on past its end, it joins.
  CHECK(join_strokes({bar, row_stroke(12, 15, 0)}, kRule).size() == 1);
}

TEST_CASE("an end joins at most one other end and no loop closes", "[drawn][joining]") {
  // Three strokes whose ends meet at one spot: two of them join, the third stays apart.
  const std::vector<Stroke> three = {row_stroke(0, 5, 0), row_stroke(7, 12, 0),
                                     line_stroke({{6, 1}, {6, 2}, {6, 3}, {6, 4}})};
  CHECK(join_strokes(three, kRule).size() == 2);
  // Four arcs of a circle with small gaps between them: every gap may join, but the last join
  // would close a loop, so they become one open stroke of all their points.
  std::vector<Stroke> arcs;
  for (int q = 0; q < 4; ++q) {
    std::vector<StrokePoint> pts;
    for (int k = 0; k <= 20; ++k) {
      const double a = (q * 90.0 + 2.0 + k * 4.3) * 3.14159265358979323846 / 180.0;
      pts.push_back({20.0 * std::cos(a), 20.0 * std::sin(a)});
    }
    arcs.push_back(line_stroke(pts));
  }
  const std::vector<Stroke> ring = join_strokes(arcs, kRule);
  REQUIRE(ring.size() == 1);
  CHECK(ring[0].points.size() == 84);
}

// A stroke's points as a comparable list, read from its lesser end.
std::vector<std::pair<double, double>> canonical(const Stroke& s) {
  std::vector<std::pair<double, double>> pts;
  for (const StrokePoint& p : s.points) pts.emplace_back(p.x, p.y);
  if (pts.back() < pts.front()) std::reverse(pts.begin(), pts.end());
  return pts;
}

TEST_CASE("strokes grouped as they stream join as they do all together", "[drawn][joining]") {
  // Thousands of short wandering strokes, in the order of their first profile (x), many within
  // the gap of others: groups are taken as soon as no stroke to come can reach them, so that the
  // grouper's index loses ends all along while it gains new ones.
  std::uint32_t seed = 12345;
  const auto random = [&seed] {  // in [0, 1)
    seed = seed * 1664525u + 1013904223u;
    return static_cast<double>(seed >> 8) / 16777216.0;
  };
  std::vector<Stroke> strokes;
  for (int first = 0; first < 3000; ++first) {
    for (int k = 0; k < 3; ++k) {
      Stroke s;
      double y = std::floor(random() * 20.0);
      const int cells = 2 + static_cast<int>(random() * 5.0);
      for (int p = first; p < first + cells; ++p) {
        s.points.push_back({static_cast<double>(p), y});
        s.chain.push_back({p, static_cast<std::int32_t>(y)});
        const double turn = random();
        y += turn < 0.1 ? -1.0 : turn > 0.9 ? 1.0 : 0.0;
      }
      s.cells = cells;
      s.length = polyline_length(s.points);
      strokes.push_back(std::move(s));
    }
  }
  StrokeGrouper grouper(kRule);
  std::vector<std::vector<std::pair<double, double>>> streamed;
  std::vector<std::size_t> roots;  // of groups not taken yet, in order
  std::size_t added = 0, most_held = 0;
  const auto take_settled = [&](double frontier) {
    std::vector<std::size_t> open;
    for (std::size_t root : roots) {
      if (grouper.group_of(root) != root) continue;  // united into another since
      if (!(grouper.reach(root) < frontier - kRule.gap - 1.0)) {
        open.push_back(root);
        continue;
      }
      std::vector<std::size_t> ids{99};  // left over from before: take_group empties it first
      grouper.take_group(root, ids);
      std::vector<Stroke> members;
      for (std::size_t id : ids) members.push_back(strokes[id]);
      for (const Stroke& j : join_strokes(members, kRule)) streamed.push_back(canonical(j));
    }
    roots = open;
    // Every stroke before the first group still open has been taken.
    grouper.forget_before(roots.empty() ? added : roots.front());
    most_held = std::max(most_held, grouper.strokes_held());
  };
  for (const Stroke& s : strokes) {
    take_settled(s.points.front().x);
    roots.push_back(grouper.add(s));
    ++added;
  }
  take_settled(1e9);
  CHECK(most_held < strokes.size() / 2);  // what it holds follows the strokes in flight
  std::vector<std::vector<std::pair<double, double>>> together;
  for (const Stroke& j : join_strokes(strokes, kRule)) together.push_back(canonical(j));
  REQUIRE(together.size() < strokes.size() * 3 / 4);  // many joins
  std::sort(streamed.begin(), streamed.end());
  std::sort(together.begin(), together.end());
  CHECK(streamed == together);
}

TEST_CASE("grouping unites two strokes exactly when they join, at turns about the limit",
          "[drawn][joining]") {
  // Stroke a runs along x to the origin; stroke b leaves from (1, 0) turned by `turn`, so that the
  // worst angle between the ends' directions and the step is the turn. Turns within a few 1e-9
  // degrees of the limit: grouping decides them by cosines, joining by the angles themselves.
  constexpr double kPi = 3.14159265358979323846;
  int joined = 0;
  for (int k = -300; k <= 300; ++k) {
    const double turn = kRule.angle_deg + k * 1e-9;
    CAPTURE(k);
    const double cx = std::cos(turn * kPi / 180.0), cy = std::sin(turn * kPi / 180.0);
    std::vector<StrokePoint> b;
    for (int j = 0; j < 5; ++j) b.push_back({1.0 + j * cx, j * cy});
    const std::vector<Stroke> pair{row_stroke(-4, 0, 0.0), line_stroke(b)};
    StrokeGrouper grouper(kRule);
    const std::size_t first = grouper.add(pair[0]), second = grouper.add(pair[1]);
    const bool joins = join_strokes(pair, kRule).size() == 1;
    CHECK((grouper.group_of(first) == grouper.group_of(second)) == joins);
    if (k < -1) CHECK(joins);
    if (k > 1) CHECK_FALSE(joins);
    joined += joins ? 1 : 0;
  }
  CHECK(joined >= 300);
}

TEST_CASE("a group once taken joins no stroke added later even one beside its ends",
          "[drawn][joining]") {
  // b carries a straight on, a cell beyond a's end: joined had a not been taken.
  const Stroke a = row_stroke(0, 4, 0.0), b = row_stroke(5, 9, 0.0);
  REQUIRE(join_strokes({a, b}, kRule).size() == 1);
  StrokeGrouper grouper(kRule);
  const std::size_t first = grouper.add(a);
  std::vector<std::size_t> members;
  grouper.take_group(first, members);
  CHECK(members == std::vector<std::size_t>{first});
  const std::size_t second = grouper.add(b);
  CHECK(grouper.group_of(second) == second);
  grouper.take_group(second, members);
  CHECK(members == std::vector<std::size_t>{second});
}

TEST_CASE("short pieces stay only where they close a gap between longer ones", "[drawn][joining]") {
  JoinRule rule = kRule;
  rule.least_piece_cells = 3;
  // A line of 5 cells, a gap, a piece of 2: the short piece hangs off the end and is left off.
  std::vector<Stroke> joined = join_strokes({row_stroke(0, 4, 0), row_stroke(6, 7, 0)}, rule);
  REQUIRE(joined.size() == 1);
  CHECK(joined[0].cells == 5);
  CHECK(joined[0].points.back().x == 4.0);
  CHECK(joined[0].length == Approx(4.0));
  // Without the rule it joins (the pen plot's merging, --min-cells 2).
  joined = join_strokes({row_stroke(0, 4, 0), row_stroke(6, 7, 0)}, kRule);
  REQUIRE(joined.size() == 1);
  CHECK(joined[0].cells == 7);
  // Between two longer pieces, given in any order, it closes the gap and stays.
  joined = join_strokes({row_stroke(9, 13, 0), row_stroke(6, 7, 0), row_stroke(0, 4, 0)}, rule);
  REQUIRE(joined.size() == 1);
  CHECK(joined[0].cells == 12);
  CHECK(joined[0].length == Approx(4.0 + 2.0 + 1.0 + 2.0 + 4.0));
  // Short pieces joined only to each other make no line: none stay.
  CHECK(
      join_strokes({row_stroke(0, 1, 0), row_stroke(3, 4, 0), row_stroke(6, 7, 0)}, rule).empty());
  // A short piece off each end of a bridged line goes; the bridge stays.
  joined = join_strokes({row_stroke(0, 1, 0), row_stroke(3, 7, 0), row_stroke(9, 10, 0),
                         row_stroke(12, 16, 0), row_stroke(18, 19, 0)},
                        rule);
  REQUIRE(joined.size() == 1);
  CHECK(joined[0].cells == 12);
  CHECK(joined[0].points.front().x == 3.0);
  CHECK(joined[0].points.back().x == 16.0);
}

TEST_CASE("drawn strokes never join across classes and are generalised after joining",
          "[drawn][joining]") {
  const HeightGrid dem = test::random_terrain(90, 110, 7);
  SilhouetteParams params;
  params.view.azimuth_deg = 90;
  params.strokes.mode = StrokeMode::drawn;
  const SilhouetteResult r = test::run_on_dem(dem, params);
  REQUIRE(!r.strokes.empty());
  const std::uint8_t factual_mark = cell::occluding, formulated_mark = cell::thinned;
  std::size_t cells = 0, factual = 0;
  for (const Stroke& s : r.strokes) {
    const std::uint8_t mark = s.cls == StrokeClass::factual ? factual_mark : formulated_mark;
    for (const ChainCell& c : s.chain) REQUIRE((r.flags(c.p, c.i) & mark));
    CHECK(s.cells >= params.chain.min_cells);
    CHECK(s.cells == static_cast<int>(s.chain.size()));
    REQUIRE(s.weights.size() == s.points.size());
    // Their memory let go too, not only emptied: it was held until each stroke was written, and
    // for a preview until the page was drawn (a third of the 8000^2 defaults' preview peak).
    CHECK(s.vertices.capacity() == 0);
    cells += static_cast<std::size_t>(s.cells);
    factual += s.cls == StrokeClass::factual;
  }
  // The statistics describe the strokes written.
  CHECK(r.stats.generalised == cells);
  CHECK(r.stats.factual_strokes == factual);
  CHECK(r.stats.formulated_strokes == r.strokes.size() - factual);
}

TEST_CASE("drawn strokes leave every stage statistic up to the t-set as the exact ones",
          "[drawn]") {
  const HeightGrid dem = test::random_terrain(120, 100, 11, 0.01);
  for (double azimuth : {90.0, 200.0}) {
    SilhouetteParams params;
    params.view.azimuth_deg = azimuth;
    const SilhouetteResult exact = test::run_on_dem(dem, params);
    params.strokes.mode = StrokeMode::drawn;
    params.geometry = Geometry::oblique;
    const SilhouetteResult drawn = test::run_on_dem(dem, params);
    CHECK(drawn.stats.valid == exact.stats.valid);
    CHECK(drawn.stats.hidden == exact.stats.hidden);
    CHECK(drawn.stats.occluding == exact.stats.occluding);
    CHECK(drawn.stats.candidate == exact.stats.candidate);
    CHECK(drawn.stats.filtered == exact.stats.filtered);
    CHECK(drawn.stats.thinned == exact.stats.thinned);
  }
}

TEST_CASE("smoothing rounds stair steps without moving a point beyond the tolerance",
          "[drawn][smoothing]") {
  std::vector<StrokePoint> zigzag;
  for (int k = 0; k <= 40; ++k) zigzag.push_back({static_cast<double>(k), (k / 2) % 2 ? 1.0 : 0.0});
  Stroke s = line_stroke(zigzag);
  for (int k = 0; k <= 40; ++k) s.vertices.push_back({10.0 * k, 100.0 + k});
  smooth_stroke(s, 1.5, 0.75, true);
  for (std::size_t k = 0; k < zigzag.size(); ++k) {
    CHECK(std::hypot(s.points[k].x - zigzag[k].x, s.points[k].y - zigzag[k].y) <= 0.75 + 1e-12);
  }
  CHECK(s.points.front().x == zigzag.front().x);
  CHECK(s.points.back().x == zigzag.back().x);
  CHECK(turning_per_length(s.points) * 3.0 < turning_per_length(zigzag));
  // A straight line stays put, its vertices' values too (a linear ramp is its own mean).
  Stroke straight = row_stroke(0, 20, 5.0);
  for (int k = 0; k <= 20; ++k) straight.vertices.push_back({2.0 * k, 7.0});
  smooth_stroke(straight, 2.0, 1.0, true);
  for (int k = 0; k <= 20; ++k) {
    CHECK(straight.points[k].y == Approx(5.0));
    CHECK(straight.vertices[k].z == Approx(7.0));
  }
  CHECK(straight.points[10].x == Approx(10.0));
  CHECK(straight.vertices[10].dist == Approx(20.0));
}

namespace {

// Smoothing written out point by point from its description, as the test's oracle: sigma in points
// at the stroke's mean spacing, a kernel out to three sigma (no farther than the stroke is long);
// a point with the whole kernel inside the stroke sums its pairs of points either side from the
// nearest (heights in the first pass excepted), any other sums the points it covers in order from
// the first and renormalises; then each point is held within `tolerance` of its anchor.
void smooth_point_by_point(Stroke& stroke, double sigma, double tolerance, bool heights,
                           const std::vector<StrokePoint>& anchors) {
  std::vector<StrokePoint>& p = stroke.points;
  const auto n = static_cast<std::ptrdiff_t>(p.size()), last = n - 1;
  double length = 0.0;
  for (std::ptrdiff_t k = 1; k < n; ++k)
    length += std::sqrt((p[k].x - p[k - 1].x) * (p[k].x - p[k - 1].x) +
                        (p[k].y - p[k - 1].y) * (p[k].y - p[k - 1].y));
  const double sp = sigma / (length / static_cast<double>(last));
  const auto reach = std::min<std::ptrdiff_t>(n, static_cast<std::ptrdiff_t>(std::ceil(3.0 * sp)));
  std::vector<double> w(static_cast<std::size_t>(reach + 1));
  for (std::ptrdiff_t j = 0; j <= reach; ++j)
    w[j] = std::exp(-0.5 * static_cast<double>(j * j) / (sp * sp));
  double whole = w[0];
  for (std::ptrdiff_t j = 1; j <= reach; ++j) whole += 2.0 * w[j];
  for (int pass = 0; pass < 3; ++pass) {
    const bool z = pass == 0 && heights;
    std::vector<StrokePoint> out = p;
    std::vector<double> zs(p.size());
    for (std::ptrdiff_t k = 1; k < last; ++k) {
      if (!z && k >= reach && k + reach <= last) {
        double sx = w[0] * p[k].x, sy = w[0] * p[k].y;
        for (std::ptrdiff_t j = 1; j <= reach; ++j) {
          sx += w[j] * (p[k - j].x + p[k + j].x);
          sy += w[j] * (p[k - j].y + p[k + j].y);
        }
        out[k] = {sx / whole, sy / whole};
        continue;
      }
      double sw = 0.0, sx = 0.0, sy = 0.0, sz = 0.0;
      for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, k - reach);
           j <= std::min(last, k + reach); ++j) {
        const double wj = w[std::abs(j - k)];
        sw += wj;
        sx += wj * p[j].x;
        sy += wj * p[j].y;
        if (z) sz += wj * stroke.vertices[j].z;
      }
      out[k] = {sx / sw, sy / sw};
      zs[k] = sz / sw;
    }
    for (std::ptrdiff_t k = 0; k < n; ++k) {
      double dx = out[k].x - anchors[k].x, dy = out[k].y - anchors[k].y;
      const double moved = dx * dx + dy * dy;
      if (moved > tolerance * tolerance) {
        const double scale = tolerance / std::sqrt(moved);
        dx *= scale, dy *= scale;
      }
      p[k] = {anchors[k].x + dx, anchors[k].y + dy};
      if (z && k > 0 && k < last) stroke.vertices[k].z = zs[k];
    }
  }
}

}  // namespace

TEST_CASE("smoothing gives the point-by-point Gaussian means bit for bit, at every length",
          "[drawn][smoothing]") {
  // Summed several points at a time in vector registers, each point's sums must still be its own,
  // added in the same order: strokes of 3 to 60 points, sigma from under one point to more than
  // the stroke, with heights and without.
  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> step(-1.0, 1.0), unit(0.0, 1.0);
  int compared = 0;
  for (int n = 3; n <= 60; ++n) {
    for (const double sigma : {0.4, 1.5, 2.7, 9.0}) {
      for (const bool heights : {false, true}) {
        Stroke s;
        std::vector<StrokePoint> anchors;
        double x = 1000.0 * unit(random), y = -500.0 * unit(random);
        for (int k = 0; k < n; ++k) {
          x += 1.0 + 0.4 * step(random);
          y += 0.8 * step(random);
          s.points.push_back({x, y});
          s.vertices.push_back({10.0 * k, 100.0 + 30.0 * unit(random)});
          anchors.push_back({x + 0.3 * step(random), y + 0.3 * step(random)});
        }
        Stroke oracle = s;
        smooth_stroke(s, sigma, 0.6, heights, &anchors);
        smooth_point_by_point(oracle, sigma, 0.6, heights, anchors);
        for (int k = 0; k < n; ++k) {
          INFO("n " << n << " sigma " << sigma << " heights " << heights << " point " << k);
          REQUIRE(s.points[k].x == oracle.points[k].x);
          REQUIRE(s.points[k].y == oracle.points[k].y);
          REQUIRE(s.vertices[k].z == oracle.vertices[k].z);
          ++compared;
        }
      }
    }
  }
  CHECK(compared == 8 * (3 + 60) * 58 / 2);
}

TEST_CASE("weights taper both ends and fall off towards the back", "[drawn][weights]") {
  Stroke s = row_stroke(0, 40, 0.0);
  for (int k = 0; k <= 40; ++k) s.vertices.push_back({0.0, 0.0});
  // The length weighed is the line's (here with a kink, longer than the row).
  Stroke kinked = s;
  kinked.points[20].y = 3.0;
  CHECK(weigh_stroke(kinked, {0.25, 0.5, 100.0}) == polyline_length(kinked.points));
  CHECK(polyline_length(kinked.points) == Approx(38.0 + 2.0 * std::sqrt(10.0)));
  CHECK(weigh_stroke(s, {0.25, 0.5, 100.0}) == Approx(40.0));
  REQUIRE(s.weights.size() == 41);
  CHECK(s.weights.front() == Approx(kTipWeight));
  CHECK(s.weights.back() == Approx(kTipWeight));
  CHECK(s.weights[20] == Approx(1.0));
  CHECK(s.weights[10] == Approx(1.0));  // a quarter of the length in
  for (int k = 1; k <= 10; ++k) CHECK(s.weights[k] > s.weights[k - 1]);
  for (int k = 0; k <= 20; ++k) CHECK(s.weights[k] == Approx(s.weights[40 - k]));
  // The same stroke at the back of the view weighs half as much, at the middle distance 3/4.
  for (StrokeVertex& v : s.vertices) v.dist = 100.0;
  weigh_stroke(s, {0.25, 0.5, 100.0});
  CHECK(s.weights[20] == Approx(0.5));
  for (StrokeVertex& v : s.vertices) v.dist = 50.0;
  weigh_stroke(s, {0.25, 0.5, 100.0});
  CHECK(s.weights[20] == Approx(0.75));
  CHECK(s.weights[0] == Approx(0.75 * kTipWeight));
}

TEST_CASE("over-extension runs the ends on along their direction", "[drawn][weights]") {
  Stroke s = line_stroke({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}});
  s.vertices.assign(5, {3.0, 4.0});
  extend_stroke(s, 0.5, 1.0);
  REQUIRE(s.points.size() == 7);
  CHECK(s.points.front().x == Approx(-0.5));
  CHECK(s.points.front().y == Approx(0.0));
  CHECK(s.points.back().x == Approx(2.0));
  CHECK(s.points.back().y == Approx(2.5));
  CHECK(s.vertices.size() == 7);
}

TEST_CASE("drawn strokes stay within the tolerance of the exact chain's cells", "[drawn]") {
  const HeightGrid dem = test::random_terrain(100, 100, 5);
  SilhouetteParams params;
  params.view.azimuth_deg = 270;
  params.strokes.mode = StrokeMode::drawn;
  params.strokes.join_gap_cells = 0.0;  // pieces as the chains are, to compare point by point
  const SilhouetteResult r = test::run_on_dem(dem, params);
  const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), 10, 10, 270);
  REQUIRE(!r.strokes.empty());
  for (const Stroke& s : r.strokes) {
    REQUIRE(s.points.size() == s.chain.size());
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      // Identity georeferencing: map coordinates are pixel positions.
      const PixelPoint cell = frame.to_pixel(s.chain[k].p, s.chain[k].i);
      const double cx = cell.col, cy = cell.row;
      // Sub-cell placement and smoothing together stay within the tolerance of the centre.
      CHECK(std::hypot(s.points[k].x - cx, s.points[k].y - cy) <=
            params.strokes.tolerance_cells + 1e-9);
    }
  }
}

TEST_CASE("drawn strokes are drawn as chains complete and do not depend on the strips",
          "[drawn][strips]") {
  const HeightGrid dem = test::random_terrain(240, 50, 21, 0.01);
  const OrientedFrame frame = make_frame(240, 50, 10, 10, 270);
  const HeightGrid z = orient(dem, frame);
  SilhouetteParams params;
  params.strokes.mode = StrokeMode::drawn;
  params.geometry = Geometry::oblique;
  const SilhouetteResult whole =
      run_silhouettes(z, frame, GeoTransform{}, ResolvedParams(params), {}, lowest_height(z));
  REQUIRE(whole.strokes.size() > 20);
  // With one thread the drawing runs on the scanning thread, so the strokes handed on before
  // finish() can be counted; with two, a drawing thread hands them on at its own pace.
  const std::pair<std::size_t, unsigned> runs[] = {{7, 1}, {40, 1}, {7, 2}};
  for (const auto& [strip, threads] : runs) {
    CAPTURE(strip, threads);
    params.threads = threads;
    std::size_t before_finish = 0;
    std::vector<Stroke> got;
    SilhouetteStream streamed(frame, GeoTransform{}, ResolvedParams(params), lowest_height(z), {},
                              [&](Stroke&& s) { got.push_back(std::move(s)); });
    for (std::size_t first = 0; first < frame.profiles; first += strip) {
      const std::size_t count = std::min(strip, frame.profiles - first);
      const std::size_t lo = first > 0 ? first - 1 : 0;
      const std::size_t hi = std::min(frame.profiles, first + count + 1);
      HeightGrid s(hi - lo, z.cols());
      for (std::size_t r = lo; r < hi; ++r) std::copy(z.row(r), z.row(r) + z.cols(), s.row(r - lo));
      streamed.add_strip(s, first, count);
    }
    if (threads == 1) before_finish = got.size();
    const SilhouetteResult r = streamed.finish();
    // A sink gets the classes interleaved; the result holds factual strokes first.
    std::stable_partition(got.begin(), got.end(),
                          [](const Stroke& s) { return s.cls == StrokeClass::factual; });
    // Most strokes were drawn and handed on while later profiles were still to come.
    if (threads == 1) CHECK(before_finish * 2 > got.size());
    REQUIRE(got.size() == whole.strokes.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      REQUIRE(got[k].points.size() == whole.strokes[k].points.size());
      for (std::size_t j = 0; j < got[k].points.size(); ++j) {
        CHECK(got[k].points[j].x == whole.strokes[k].points[j].x);
        CHECK(got[k].points[j].y == whole.strokes[k].points[j].y);
        CHECK(got[k].weights[j] == whole.strokes[k].weights[j]);
      }
    }
    CHECK(r.stats.generalised == whole.stats.generalised);
  }
}

TEST_CASE("a chain that leaps along the line of sight is cut there", "[drawn][splitting]") {
  // Five cells on consecutive profiles; between the third and fourth the chain leaps 10 cells.
  StrokeBuilder builder;
  const double along[] = {0, 1, 1, 11, 12};
  for (int k = 0; k < 5; ++k) {
    StrokeCell c;
    c.cell = {k, static_cast<std::int32_t>(along[k])};
    c.map = c.point = {static_cast<double>(k), along[k]};
    c.dist = 10.0 * along[k];
    c.z = 100.0 + k;
    c.slope_pct = 10.0 * (k + 1);
    c.row_slope_pct = 1.0;
    c.depth_m = 2.0 * k;
    builder.add(c, true);
  }
  std::vector<Stroke> pieces;
  builder.drawn_pieces(StrokeClass::factual, 4.0, pieces);
  REQUIRE(pieces.size() == 2);
  CHECK(pieces[0].cells == 3);
  CHECK(pieces[1].cells == 2);
  CHECK(pieces[0].length == Approx(1.0 + std::sqrt(2.0)));
  CHECK(pieces[1].length == Approx(std::sqrt(2.0)));
  CHECK(pieces[0].mean_slope_pct == Approx(20.0));  // cells 1-3: 10, 20, 30
  CHECK(pieces[1].mean_slope_pct == Approx(45.0));  // 40, 50
  CHECK(pieces[1].max_depth_m == Approx(8.0));
  CHECK(pieces[1].chain.front().p == 3);
  REQUIRE(pieces[1].vertices.size() == 2);
  CHECK(pieces[1].vertices[0].dist == 110.0);
  CHECK(pieces[1].vertices[1].z == 104.0);
  // Without a leap the stroke stays whole, its attributes those of all its cells.
  std::vector<Stroke> whole;
  builder.drawn_pieces(StrokeClass::factual, 20.0, whole);
  REQUIRE(whole.size() == 1);
  CHECK(whole[0].cells == 5);
  CHECK(whole[0].mean_slope_pct == Approx(30.0));
  CHECK(whole[0].mean_dist == Approx(50.0));  // 0, 10, 10, 110, 120
  CHECK(whole[0].points.size() == 5);
}

TEST_CASE("the drawing takes its pieces a batch at a time, however many a batch of profiles makes",
          "[drawn][memory]") {
  // Pieces far apart, each its own group and settled at once: with the drawing on the caller's
  // thread, a flush draws and hands on all it was given. A piece is added, then a settle, so a
  // batch of steps is half as many pieces.
  const OrientedFrame frame = make_frame(20, 20, 10, 10, 270);
  SilhouetteParams params;
  params.strokes.mode = StrokeMode::drawn;
  const DrawingSetup setup = drawing_setup(frame, GeoTransform{}, params, 0.0);
  std::size_t handed_on = 0;
  DrawingPipeline drawing(setup, false, [&](StrokeClass, std::size_t, Stroke&&) { ++handed_on; });
  const std::size_t batch = DrawingPipeline::kStepsPerBatch / 2;
  for (std::size_t k = 0; k < 3 * batch; ++k) {
    Stroke piece = row_stroke(0, 4, 100.0 * static_cast<double>(k));
    piece.cls = StrokeClass::formulated;
    piece.mean_slope_pct = 30.0;
    for (int i = 0; i <= 4; ++i) {
      piece.chain.push_back({static_cast<std::int32_t>(k), i});
      piece.vertices.push_back({10.0 * i, 100.0, 0.0});
    }
    drawing.add_piece(StrokeClass::formulated, std::move(piece));
    drawing.settle(StrokeClass::formulated, static_cast<double>(k) + 100.0);
    drawing.flush_when_full();
    // Never more than a batch of steps waits for the drawing.
    REQUIRE(k + 1 - handed_on <= batch);
  }
  CHECK(handed_on == 3 * batch);
  drawing.finish();
  CHECK(handed_on == 3 * batch);
}
