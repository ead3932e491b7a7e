// Panorama sketches (docs/PANORAMA.md): analytic terrains with answers worked out by hand here,
// and the panorama of a turned DEM.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <vector>

#include "catch_compat.h"
#include "core/panorama/panorama.h"
#include "test_support.h"

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCell = 10.0;

// North-up georeferencing with 10 m cells, the grid's north-west corner at (0, rows * 10).
GeoTransform north_up(std::size_t rows) {
  GeoTransform gt;
  gt.a = {0.0, kCell, 0.0, static_cast<double>(rows) * kCell, 0.0, -kCell};
  return gt;
}

// The map position of the centre of cell (row, col).
StrokePoint centre(const GeoTransform& gt, std::size_t row, std::size_t col) {
  StrokePoint p{};
  gt.apply({static_cast<double>(col) + 0.5, static_cast<double>(row) + 0.5}, p.x, p.y);
  return p;
}

HeightGrid terrain(std::size_t rows, std::size_t cols,
                   const std::function<double(double x, double y)>& height) {
  HeightGrid dem(rows, cols);
  const GeoTransform gt = north_up(rows);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) {
      const StrokePoint p = centre(gt, r, c);
      dem(r, c) = static_cast<float>(height(p.x, p.y));
    }
  return dem;
}

PanoramaParams looking_from(const StrokePoint& observer, double eye_height) {
  PanoramaParams params;
  params.view.observer_x = observer.x;
  params.view.observer_y = observer.y;
  params.view.observer_height = eye_height;
  params.record_visibility = true;
  return params;
}

// The hidden zone's far end behind a wall, worked out from the geometry: the first distance, in
// centimetre steps, where the apparent ground rises above the sight line over the wall's top.
double wall_shadow_end(double wall_distance, double wall_height, double eye, double k, double R) {
  const auto drop = [&](double d) { return (1.0 - k) * d * d / (2.0 * R); };
  const double sight = (wall_height - drop(wall_distance) - eye) / wall_distance;
  double d = wall_distance;
  while ((-drop(d) - eye) / d < sight) d += 0.01;
  return d;
}

}  // namespace

TEST_CASE("a cone seen from outside has its silhouette on the tangent rays", "[panorama]") {
  const std::size_t n = 301;
  const double apex_x = 1505, apex_y = 1505, radius = 600, height = 300;
  const HeightGrid dem = terrain(n, n, [&](double x, double y) {
    return std::max(0.0, height * (1.0 - std::hypot(x - apex_x, y - apex_y) / radius));
  });
  const GeoTransform gt = north_up(n);
  const StrokePoint eye_at = centre(gt, 150, 10);  // due west of the apex, 1400 m away
  PanoramaParams params = looking_from(eye_at, 2.0);
  params.view.azimuth_from = 45, params.view.azimuth_to = 135;
  params.view.max_distance = 2200;
  const PanoramaResult result = sketch_panorama(dem, gt, params);
  const double distance = apex_x - eye_at.x;
  const double half_angle = std::asin(radius / distance) * 180.0 / kPi;
  double lo = 1e9, hi = -1e9;
  for (const PanoramaStroke& s : result.strokes) {
    if (s.map.cls != StrokeClass::factual) continue;
    lo = std::min(lo, s.azimuth_min), hi = std::max(hi, s.azimuth_max);
    for (const StrokePoint& p : s.map.points)  // every occluder lies on the cone
      CHECK(std::hypot(p.x - apex_x, p.y - apex_y) <= radius + 1.5 * kCell);
  }
  // Within a ray spacing, and the cell of bilinear reach at the cone's rim.
  const double tolerance = result.rays.ray_spacing_deg() + kCell / distance * 180.0 / kPi;
  CHECK(std::fabs(lo - (90.0 - half_angle)) <= tolerance);
  CHECK(std::fabs(hi - (90.0 + half_angle)) <= tolerance);
}

TEST_CASE("the horizon of a plain on a curved earth lies where geometry puts it", "[panorama]") {
  const double eye = 10.0, k = 0.13, R = 6371000.0;
  const double horizon = std::sqrt(2.0 * R * eye / (1.0 - k));  // 12.1 km
  const std::size_t rows = 21, cols = 1500;
  const HeightGrid dem(rows, cols, 0.0f);
  const GeoTransform gt = north_up(rows);
  PanoramaParams params = looking_from(centre(gt, 10, 0), eye);
  params.view.azimuth_from = 89, params.view.azimuth_to = 91;
  const PanoramaResult result = sketch_panorama(dem, gt, params);
  const Grid<std::uint8_t> seen = visibility_raster(result, rows, cols, gt);
  // Along the observer's row: visible out to the horizon, hidden beyond.
  std::size_t last_visible = 0;
  for (std::size_t c = 0; c < cols; ++c)
    if (seen(10, c) == visibility_code::visible) last_visible = c;
  CHECK(std::fabs(static_cast<double>(last_visible) * kCell - horizon) <= kCell);
  CHECK(seen(10, cols - 1) == visibility_code::hidden);
  // The horizon is a factual silhouette.
  REQUIRE(result.stats.factual_strokes >= 1);
  for (const PanoramaStroke& s : result.strokes)
    if (s.map.cls == StrokeClass::factual) CHECK(std::fabs(s.map.mean_dist - horizon) <= kCell);
}

TEST_CASE("the zone hidden behind a wall ends where the sight line over it meets the ground",
          "[panorama]") {
  const std::size_t rows = 41, cols = 400;
  const double wall_height = 8.0, k = 0.13, R = 6371000.0;
  // A wall three cells thick, so that its top is flat between cell centres 100 and 102.
  const HeightGrid dem = terrain(
      rows, cols, [&](double x, double) { return x > 1000 && x < 1030 ? wall_height : 0.0; });
  const GeoTransform gt = north_up(rows);
  const StrokePoint eye_at = centre(gt, 20, 0);
  const double wall_distance = 1025.0 - eye_at.x;  // the far edge of the wall's flat top
  for (const double eye : {12.0, 20.0, 6.0}) {
    CAPTURE(eye);
    PanoramaParams params = looking_from(eye_at, eye);
    params.view.azimuth_from = 80, params.view.azimuth_to = 100;
    const PanoramaResult result = sketch_panorama(dem, gt, params);
    const Grid<std::uint8_t> seen = visibility_raster(result, rows, cols, gt);
    std::size_t first_seen_again = cols;
    for (std::size_t c = 103; c < cols && first_seen_again == cols; ++c)
      if (seen(20, c) == visibility_code::visible) first_seen_again = c;
    CHECK(seen(20, 103) == visibility_code::hidden);
    if (eye > wall_height) {
      const double end = wall_shadow_end(wall_distance, wall_height, eye, k, R);
      CHECK(std::fabs(centre(gt, 20, first_seen_again).x - eye_at.x - end) <= kCell);
    } else {
      CHECK(first_seen_again == cols);  // the zone reaches the end of the DEM
    }
  }
}

}  // namespace tsk

namespace tsk {

TEST_CASE("a DEM turned a quarter about the observer turns the panorama a quarter of azimuth",
          "[panorama][invariance]") {
  const std::size_t n = 121;
  const HeightGrid dem = test::random_terrain(n, n, 5);
  const HeightGrid turned = test::rotate_clockwise(dem);
  const GeoTransform gt = north_up(n);
  const PanoramaParams params = looking_from({605.0, 605.0}, 30.0);  // the centre cell's centre
  const PanoramaResult a = sketch_panorama(dem, gt, params);
  const PanoramaResult b = sketch_panorama(turned, gt, params);
  REQUIRE(a.rays.rays == b.rays.rays);
  CHECK(a.stats.hidden == b.stats.hidden);
  CHECK(a.stats.occluding == b.stats.occluding);
  CHECK(a.stats.candidate == b.stats.candidate);
  CHECK(a.stats.thinned == b.stats.thinned);
  // Every stroke comes back a quarter turn on, with the same cells and length.
  REQUIRE(a.strokes.size() == b.strokes.size());
  REQUIRE(a.strokes.size() > 10);
  std::multimap<long, const PanoramaStroke*> by_start;
  for (const PanoramaStroke& s : b.strokes)
    by_start.emplace(std::lround(std::fmod(s.view.front().x, 360.0) * 1000.0), &s);
  for (const PanoramaStroke& s : a.strokes) {
    const long turned_start = std::lround(std::fmod(s.view.front().x + 90.0, 360.0) * 1000.0);
    const auto [lo, hi] = by_start.equal_range(turned_start);
    const auto match = std::find_if(lo, hi, [&](const auto& entry) {
      const PanoramaStroke& t = *entry.second;
      return t.map.cls == s.map.cls && t.map.cells == s.map.cells &&
             std::fabs(t.map.length - s.map.length) < 1e-6 &&
             std::fabs(t.view.front().y - s.view.front().y) < 1e-9;
    });
    CHECK(match != hi);
  }
  // And so does the visibility raster.
  const Grid<std::uint8_t> seen_a = visibility_raster(a, n, n, gt);
  const Grid<std::uint8_t> seen_b = visibility_raster(b, n, n, gt);
  std::size_t same = 0;
  for (std::size_t r = 0; r < n; ++r)
    for (std::size_t c = 0; c < n; ++c) same += seen_b(r, c) == seen_a(n - 1 - c, r);
  CHECK(same >= n * n * 999 / 1000);
}

}  // namespace tsk

namespace tsk {

TEST_CASE("a peak is labelled when the eye reaches its top, and only then", "[panorama][peaks]") {
  // The wall of the shadow test, 8 m high at 1000-1030 m east of the grid's west edge, seen
  // from 12 m above the west edge: its shadow ends where the sight line over it meets the ground.
  // Far off, a ridge 30 m high.
  const std::size_t rows = 41, cols = 400;
  const HeightGrid dem = terrain(rows, cols, [](double x, double) {
    if (x > 1000 && x < 1030) return 8.0;
    return std::max(0.0, 30.0 - 0.6 * std::fabs(x - 3555.0));  // a ridge, its crest at 3555 m
  });
  const GeoTransform gt = north_up(rows);
  const StrokePoint eye_at = centre(gt, 20, 0);
  PanoramaView view;
  view.observer_x = eye_at.x, view.observer_y = eye_at.y;
  view.observer_height = 12;
  view.azimuth_from = 45, view.azimuth_to = 135;
  const PanoramaRays rays = plan_rays(dem, gt, view);
  const double shadow_end = eye_at.x + wall_shadow_end(1025.0 - eye_at.x, 8.0, 12.0, 0.13, 6371000);
  const std::vector<NamedPoint> peaks = {
      {"on the wall", 1015, eye_at.y},
      {"in its shadow", 1500, eye_at.y},
      {"past the shadow", shadow_end + 50, eye_at.y},
      {"a hill far off", 3555, eye_at.y},
      {"behind the viewer", 2000, eye_at.y + 2000 * 5},  // north: outside the field of view
      {"off the DEM", 5000, eye_at.y}};
  const std::vector<SeenPeak> seen = see_peaks(dem, gt, rays, peaks);
  std::vector<std::string> names;
  for (const SeenPeak& s : seen) names.push_back(s.name);
  CHECK(names == std::vector<std::string>{"on the wall", "past the shadow", "a hill far off"});
  REQUIRE(seen.size() == 3);
  // Where they stand in the panorama: due east, at the elevation angle of their tops.
  CHECK(seen[0].azimuth_deg == Approx(90.0));
  const double d = 1015 - eye_at.x;
  const double expected = std::atan((8.0 - 0.87 * d * d / (2 * 6371000.0) - 12.0) / d);
  CHECK(seen[0].elevation_deg == Approx(expected * 180.0 / kPi).epsilon(1e-9));
  CHECK(seen[2].distance == Approx(3555 - eye_at.x));
}

}  // namespace tsk

namespace tsk {

TEST_CASE("peak labels stand above the skyline, in rows where they would overlap",
          "[panorama][peaks]") {
  const auto peak = [](const char* name, double azimuth, double elevation) {
    SeenPeak p;
    p.name = name, p.azimuth_deg = azimuth, p.elevation_deg = elevation;
    return p;
  };
  // Given out of azimuth order; labels 5 degrees wide, rows 0.5 degrees apart above 2 degrees.
  const std::vector<PeakLeader> leaders =
      peak_leaders({peak("C", 30, 1.0), peak("A", 10, 1.5), peak("B", 12, 0.5), peak("D", 14, 0.2)},
                   2.0, 0.5, 5.0);
  REQUIRE(leaders.size() == 4);
  std::string order;
  for (const PeakLeader& l : leaders) {
    order += l.peak.name;
    CHECK(l.top.x == l.peak.azimuth_deg);  // straight up from the peak's top
    CHECK(l.label.x == l.top.x);
    CHECK(l.top.y == l.peak.elevation_deg);
  }
  CHECK(order == "ABDC");
  CHECK(leaders[0].label.y == 2.5);  // A: the first row
  CHECK(leaders[1].label.y == 3.0);  // B: 2 degrees after A, a row up
  CHECK(leaders[2].label.y == 3.5);  // D: within both A's and B's labels
  CHECK(leaders[3].label.y == 2.5);  // C: clear of them all, back on the first row
}

}  // namespace tsk

namespace tsk {

TEST_CASE("drawn panorama strokes end where their chains leap along the rays",
          "[panorama][strokes]") {
  const std::size_t n = 121;
  const HeightGrid dem = test::random_terrain(n, n, 9);
  const GeoTransform gt = north_up(n);
  PanoramaParams params = looking_from({605.0, 605.0}, 30.0);
  params.chain.min_cells = 2;  // the least: one sample is noise
  const PanoramaResult chains = sketch_panorama(dem, gt, params);
  params.cut_leaps = true;
  const PanoramaResult cut = sketch_panorama(dem, gt, params);
  const auto leaps = [](const PanoramaStroke& s) {
    std::size_t count = 0;
    for (std::size_t k = 1; k < s.map.chain.size(); ++k)
      count += std::abs(s.map.chain[k].i - s.map.chain[k - 1].i) > PanoramaLinker::kLeapCells;
    return count;
  };
  std::size_t leaps_in_chains = 0, leaps_in_cut = 0;
  for (const PanoramaStroke& s : chains.strokes) leaps_in_chains += leaps(s);
  for (const PanoramaStroke& s : cut.strokes) leaps_in_cut += leaps(s);
  REQUIRE(leaps_in_chains > 0);
  CHECK(leaps_in_cut == 0);
  // Cut, not moved: the chains' cells, in at most one more stroke per leap (a piece of one
  // sample is dropped as noise).
  std::set<std::pair<std::int32_t, std::int32_t>> chain_cells;
  for (const PanoramaStroke& s : chains.strokes)
    for (const ChainCell& c : s.map.chain) chain_cells.insert({c.p, c.i});
  for (const PanoramaStroke& s : cut.strokes)
    for (const ChainCell& c : s.map.chain) CHECK(chain_cells.count({c.p, c.i}) == 1);
  CHECK(cut.strokes.size() > chains.strokes.size());
  CHECK(cut.strokes.size() <= chains.strokes.size() + leaps_in_chains);
  CHECK(cut.stats.generalised <= chains.stats.generalised);
  CHECK(cut.stats.thinned == chains.stats.thinned);
}

}  // namespace tsk

namespace tsk {

// Where the zone hidden behind a ridge ends along ray r, worked out here from the heights the
// DEM holds: along a ray of azimuth a over a terrain that changes only eastward, the DEM's
// bilinear surface is the heights of the cells' centres joined by straight lines. Walked in
// centimetre steps, without the curvature (the earth made flat by its radius).
double ridge_shadow_end(const HeightGrid& dem, double azimuth_deg, double eye, double from_x) {
  const double east = std::sin(azimuth_deg * kPi / 180.0);
  const auto ground = [&](double d) {
    const double col = (from_x + d * east) / kCell - 0.5;
    const auto left = static_cast<std::size_t>(col);
    const double t = col - static_cast<double>(left);
    return (1.0 - t) * dem(0, left) + t * dem(0, left + 1);
  };
  double highest = -1e9;
  bool hidden = false;
  for (double d = 0.01;; d += 0.01) {
    const double tangent = (ground(d) - eye) / d;
    if (tangent < highest) {
      hidden = true;
    } else if (hidden) {
      return d;
    }
    highest = std::max(highest, tangent);
  }
}

TEST_CASE("more samples per cell find where a hidden zone ends within their finer step",
          "[panorama]") {
  const std::size_t rows = 21, cols = 120;
  // A ridge running north-south 500 m east of the observer, then ground rising eastward, so
  // that the sight line over the ridge meets the ground at a clear angle.
  const HeightGrid dem = terrain(rows, cols, [](double x, double) {
    return 30.0 * std::exp(-std::pow((x - 560.0) / 40.0, 2)) + 0.12 * std::max(0.0, x - 640.0);
  });
  const GeoTransform gt = north_up(rows);
  const StrokePoint eye_at = centre(gt, 10, 5);
  for (const double eye : {3.0, 7.3, 12.9}) {
    for (const int per_cell : {1, 2, 4, 8}) {
      CAPTURE(eye, per_cell);
      PanoramaParams params = looking_from(eye_at, eye);
      params.view.azimuth_from = 85, params.view.azimuth_to = 95;
      params.view.earth_radius = 1e15;
      params.view.samples_per_cell = per_cell;
      const PanoramaResult result = sketch_panorama(dem, gt, params);
      const PanoramaRays& rays = result.rays;
      REQUIRE(rays.step == Approx(kCell / per_cell));
      const std::size_t r = rays.rays / 2;
      std::size_t first_seen_again = 0;
      bool hidden = false;
      for (std::size_t k = 0; k < rays.samples && first_seen_again == 0; ++k) {
        const std::uint8_t bits = result.sample_class_of(r, k);
        if (bits == sample_class::hidden) hidden = true;
        if (bits == sample_class::visible && hidden) first_seen_again = k;
      }
      REQUIRE(first_seen_again > 0);
      const double found = rays.distance(first_seen_again + 1);
      const double end = ridge_shadow_end(dem, rays.azimuth_deg(r), eye, eye_at.x);
      CHECK(found >= end - 0.01);
      CHECK(found <= end + rays.step + 0.01);
    }
  }
  PanoramaView view;
  view.observer_x = eye_at.x, view.observer_y = eye_at.y;
  for (const int refused : {0, kMostSamplesPerCell + 1}) {
    view.samples_per_cell = refused;
    CHECK_THROWS_WITH(view.validate(), Catch::Contains("samples per cell must be from 1 to 8"));
  }
}

TEST_CASE("the shortest panorama stroke is counted in cells, whatever the samples per cell",
          "[panorama][strokes]") {
  const std::size_t n = 121;
  const HeightGrid dem = test::random_terrain(n, n, 5);
  const GeoTransform gt = north_up(n);
  for (const int per_cell : {1, 2, 3}) {
    CAPTURE(per_cell);
    PanoramaParams params = looking_from({605.0, 605.0}, 30.0);
    params.view.samples_per_cell = per_cell;
    // A stroke crosses a ray a sample: per_cell rays to a cell at the far end.
    const auto shortest = [&](int min_cells) {
      params.chain.min_cells = min_cells;
      const PanoramaResult result = sketch_panorama(dem, gt, params);
      REQUIRE(result.strokes.size() > 10);
      std::size_t least = result.strokes.front().map.chain.size();
      for (const PanoramaStroke& s : result.strokes) least = std::min(least, s.map.chain.size());
      return least;
    };
    CHECK(shortest(3) >= static_cast<std::size_t>(3 * per_cell));
    CHECK(shortest(2) < static_cast<std::size_t>(3 * per_cell));  // such strokes are there
  }
}

TEST_CASE("a panorama that would take far more samples than the DEM has cells is refused",
          "[panorama]") {
  // 48 x 48 cells a metre wide and ten kilometres tall: the rays, a metre apart at a range of
  // 480 km, would number three million, of 480 000 samples each.
  const HeightGrid dem(48, 48, 100.0f);
  GeoTransform gt;
  gt.a = {0.0, 1.0, 0.0, 480000.0, 0.0, -10000.0};
  PanoramaView view;
  view.observer_x = 24.0, view.observer_y = 240000.0;
  try {
    plan_rays(dem, gt, view);
    FAIL("not refused");
  } catch (const Error& e) {
    CHECK_THAT(e.what(), Catch::Contains("far from square"));
  }
  // Square cells of the same DEM are drawn.
  gt.a = {0.0, 10.0, 0.0, 480.0, 0.0, -10.0};
  view.observer_y = 240.0, view.observer_x = 240.0;
  CHECK(plan_rays(dem, gt, view).rays > 0);
}

}  // namespace tsk

namespace tsk {

TEST_CASE("a panorama reports its progress and stops when told to", "[panorama]") {
  // Enough rays (3 560 of 566 samples) for more than one batch of about a million samples.
  const std::size_t n = 801;
  const HeightGrid dem = test::random_terrain(n, n, 3);
  const PanoramaParams params = looking_from({4005.0, 4005.0}, 30.0);
  std::vector<double> seen;
  sketch_panorama(dem, north_up(n), params, [&](double fraction) {
    seen.push_back(fraction);
    return true;
  });
  REQUIRE(seen.size() > 1);
  CHECK(std::is_sorted(seen.begin(), seen.end()));
  CHECK(seen.back() == 1.0);
  std::size_t calls = 0;
  CHECK_THROWS_AS(sketch_panorama(dem, north_up(n), params, [&](double) { return ++calls < 2; }),
                  Cancelled);
  CHECK(calls == 2);  // stopped at once
}

}  // namespace tsk

namespace tsk {

namespace {

// The rays from the middle of a 2 km square DEM over the field from `from` to `to` degrees.
PanoramaRays rays_over(double from, double to) {
  const HeightGrid dem(200, 200, 100.0f);
  PanoramaView view;
  view.observer_x = 1000.0, view.observer_y = 1000.0;
  view.azimuth_from = from, view.azimuth_to = to;
  return plan_rays(dem, north_up(200), view);
}

// Direction k of a fine irregular spread all round O, every fifth one within 3e-8 degrees of a
// band edge (the close bearing alone would miss them), every fifth other one within 5e-3 degrees
// of the field's end: (east, north), of lengths 1 to 13.
PixelPoint test_direction(int k, const PanoramaRays& rays, double from, double to) {
  double bearing = std::fmod(k * 0.0137 + (k % 7) * 1e-7, 360.0);
  if (k % 5 == 0)
    bearing = std::fmod(from + (k % 997) * rays.ray_spacing_deg() + 3e-8 * (k % 3 - 1), 360.0);
  if (k % 5 == 1) bearing = std::fmod(to + 360.0 + 1e-3 * (k % 11 - 5), 360.0);
  const double radians = bearing * kPi / 180.0, length = 1 + k % 13;
  return {std::sin(radians) * length, std::cos(radians) * length};
}

}  // namespace

TEST_CASE("the ray locator finds the band that the exact bearing falls in", "[panorama]") {
  // Brute force: libm's atan2, the band floor(offset / spacing), for directions all round O,
  // near the bands' edges and the field's ends too.
  for (const auto& [from, to] : {std::pair{0.0, 360.0}, {300.0, 30.0}, {10.0, 200.0}}) {
    CAPTURE(from, to);
    const PanoramaRays rays = rays_over(from, to);
    const RayLocator locator(rays);
    const double spacing = rays.ray_spacing_deg();
    std::size_t checked = 0, inside = 0;
    for (int k = 0; k < 200000; ++k) {
      const PixelPoint direction = test_direction(k, rays, from, to);
      const double east = direction.col, north = direction.row;
      const double offset = rays.field.offset_deg(std::atan2(east, north) * 180.0 / kPi);
      const double in_band = offset / spacing;
      // Directions within 1e-9 of a band's edge may go either way.
      if (std::fabs(in_band - std::round(in_band)) * spacing < 1e-9) continue;
      const std::size_t expected = offset < rays.field.width_deg
                                       ? std::min(rays.rays - 1, static_cast<std::size_t>(in_band))
                                       : rays.rays;
      REQUIRE(locator.ray_of(east, north) == expected);
      ++checked;
      inside += expected < rays.rays;
    }
    CHECK(checked > 150000);
    CHECK(inside > 0);
  }
}

}  // namespace tsk

namespace tsk {

TEST_CASE("the ray locator's walk from a hint finds the band ray_of finds, whatever the hint",
          "[panorama]") {
  // Fields: the full circle, across north, wider than half a turn, a narrow one.
  for (const auto& [from, to] :
       {std::pair{0.0, 360.0}, {300.0, 30.0}, {10.0, 290.0}, {44.0, 46.0}}) {
    CAPTURE(from, to);
    const PanoramaRays rays = rays_over(from, to);
    const RayLocator locator(rays);
    std::size_t walked = 0;
    for (int k = 0; k < 200000; ++k) {
      const PixelPoint direction = test_direction(k, rays, from, to);
      const double east = direction.col, north = direction.row;
      const std::size_t expected = locator.ray_of(east, north);
      // Hints: the band itself, its neighbours a few rays off, rays far away, and none.
      const std::size_t near = expected < rays.rays ? expected : k % rays.rays;
      const std::size_t offset = static_cast<std::size_t>(k % 9);
      for (const std::size_t hint :
           {near, near + offset, near >= offset ? near - offset : 0,
            (near + rays.rays / 2) % rays.rays, std::size_t{0}, rays.rays - 1, rays.rays}) {
        const std::size_t found =
            locator.ray_near(east, north, std::hypot(east, north), std::min(hint, rays.rays));
        REQUIRE(found == expected);
        ++walked;
      }
    }
    CHECK(walked == 7 * 200000);
  }
}

TEST_CASE("the visibility raster takes each cell's class from its nearest sample on its ray",
          "[panorama]") {
  // Cell by cell, from the sample nearest the cell's centre, on the ray ray_of gives: views all
  // round, across north and narrow, from the middle and a corner, with rows through O.
  const std::size_t rows = 150, cols = 170;
  const HeightGrid dem = terrain(rows, cols, [](double x, double y) {
    return 40.0 * std::sin(x / 170.0) * std::cos(y / 130.0) + 0.02 * x;
  });
  const GeoTransform gt = north_up(rows);
  struct View {
    std::size_t row, col;
    double from, to;
    int per_cell;
  };
  for (const View& v : {View{75, 85, 0, 360, 1}, View{75, 85, 300, 30, 2}, View{2, 3, 100, 170, 1},
                        View{149, 169, 280, 10, 1}, View{40, 120, 200, 201, 3}}) {
    CAPTURE(v.row, v.col, v.from, v.to, v.per_cell);
    PanoramaParams params = looking_from(centre(gt, v.row, v.col), 3.0);
    params.view.azimuth_from = v.from, params.view.azimuth_to = v.to;
    params.view.samples_per_cell = v.per_cell;
    const PanoramaResult result = sketch_panorama(dem, gt, params);
    const PanoramaRays& rays = result.rays;
    const RayLocator locator(rays);
    const Grid<std::uint8_t> seen = visibility_raster(result, rows, cols, gt, 2);
    std::map<std::uint8_t, std::size_t> codes;
    for (std::size_t r = 0; r < rows; ++r) {
      for (std::size_t c = 0; c < cols; ++c) {
        const StrokePoint p = centre(gt, r, c);
        const double dx = p.x - rays.observer_x, dy = p.y - rays.observer_y;
        const double nearest = std::floor(std::sqrt(dx * dx + dy * dy) / rays.step + 0.5);
        std::uint8_t expected = visibility_code::visible;
        if (nearest > static_cast<double>(rays.samples)) {
          expected = visibility_code::out_of_range;
        } else if (nearest >= 1.0) {
          const std::size_t ray = locator.ray_of(dx, dy);
          const std::uint8_t bits =
              ray == rays.rays ? sample_class::out
                               : result.sample_class_of(ray, static_cast<std::size_t>(nearest) - 1);
          expected = bits == sample_class::visible  ? visibility_code::visible
                     : bits == sample_class::hidden ? visibility_code::hidden
                                                    : visibility_code::out_of_range;
        }
        REQUIRE(seen(r, c) == expected);
        ++codes[expected];
      }
    }
    CHECK(codes[visibility_code::visible] > 0);
    CHECK(codes[visibility_code::hidden] + codes[visibility_code::out_of_range] > 0);
  }
}

}  // namespace tsk

namespace tsk {

TEST_CASE("the visibility raster reports its progress and stops when told", "[panorama]") {
  const std::size_t n = 300;
  const HeightGrid dem = terrain(n, n, [](double x, double y) { return std::hypot(x, y) / 50.0; });
  const GeoTransform gt = north_up(n);
  const PanoramaResult result = sketch_panorama(dem, gt, looking_from(centre(gt, 150, 150), 2.0));
  // One thread: parallel_for reports from the caller's thread alone, so with a helper the count
  // of reports (and whether a stop is asked for before the helper has done every row) depends on
  // how the two threads are scheduled; under a loaded ctest run the caller reported twice.
  std::vector<double> told;
  visibility_raster(result, n, n, gt, 1, [&](double fraction) {
    told.push_back(fraction);
    return true;
  });
  REQUIRE(told.size() > 2);
  CHECK(std::is_sorted(told.begin(), told.end()));
  CHECK(told.front() > 0.0);
  CHECK(told.back() <= 1.0);
  std::size_t calls = 0;
  CHECK_THROWS_AS(visibility_raster(result, n, n, gt, 1, [&](double) { return ++calls < 2; }),
                  Cancelled);
  CHECK(calls == 2);  // stopped at once
}

}  // namespace tsk
