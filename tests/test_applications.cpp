// Diagnostics maps and the profile plot.
#include <cmath>
#include <cstring>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

struct Oriented {
  OrientedFrame frame;
  HeightGrid z;
  SilhouetteResult result;
};

Oriented run_view(const HeightGrid& dem, double azimuth, double cell = 10) {
  Oriented o;
  o.frame = make_frame(dem.rows(), dem.cols(), cell, cell, azimuth);
  o.z = orient(dem, o.frame);
  SilhouetteParams params;
  params.view.azimuth_deg = azimuth;
  o.result = run_silhouettes(o.z, o.frame, GeoTransform{}, ResolvedParams(params));
  return o;
}

}  // namespace

TEST_CASE("each cell gets its most specific class", "[diagnostics]") {
  CHECK(cell_class(0) == CellClass::nodata);
  CHECK(cell_class(cell::valid) == CellClass::visible);
  CHECK(cell_class(cell::valid | cell::hidden) == CellClass::hidden);
  CHECK(cell_class(cell::valid | cell::hidden | cell::candidate) == CellClass::candidate);
  CHECK(cell_class(cell::valid | cell::occluding) == CellClass::occluding);
  CHECK(cell_class(cell::valid | cell::candidate | cell::filtered) == CellClass::filtered);
  CHECK(cell_class(cell::valid | cell::candidate | cell::filtered | cell::thinned) ==
        CellClass::thinned);
  CHECK(std::string(cell_class_name(CellClass::filtered)) == "f-set");
}

TEST_CASE("the classification map lies on the DEM grid for every cardinal view", "[diagnostics]") {
  const HeightGrid dem = test::random_terrain(30, 45, 12, 0.05);
  for (double az : {0.0, 90.0, 180.0, 270.0}) {
    CAPTURE(az);
    const Oriented o = run_view(dem, az);
    const Grid<std::uint8_t> map = classification_map(o.result.flags, o.frame);
    REQUIRE(map.rows() == 30);
    REQUIRE(map.cols() == 45);
    for (std::size_t p = 0; p < o.frame.profiles; ++p)
      for (std::size_t i = 0; i < o.frame.length; ++i)
        REQUIRE(map(o.frame.dem_row(p, i), o.frame.dem_col(p, i)) ==
                static_cast<std::uint8_t>(cell_class(o.result.flags(p, i))));
    for (std::size_t r = 0; r < 30; ++r)
      for (std::size_t c = 0; c < 45; ++c) REQUIRE((map(r, c) == 0) == !is_data(dem(r, c)));
  }
}

TEST_CASE("a resampled view maps every interior DEM cell to a class", "[diagnostics]") {
  const HeightGrid dem = test::random_terrain(40, 40, 13);
  const Oriented o = run_view(dem, 30);
  const Grid<std::uint8_t> map = classification_map(o.result.flags, o.frame);
  for (std::size_t r = 2; r < 38; ++r)
    for (std::size_t c = 2; c < 38; ++c) REQUIRE(map(r, c) != 0);
}

TEST_CASE("row slope is the slope across the line of sight", "[diagnostics]") {
  // A plane rising 20 % to the north: across a view facing azimuth t its slope is 20 |sin t| %.
  const double a = 0.2;
  HeightGrid dem(40, 40);
  for (std::size_t r = 0; r < 40; ++r)
    for (std::size_t c = 0; c < 40; ++c) dem(r, c) = static_cast<float>(a * 10.0 * (40.0 - r));
  for (double az : {90.0, 0.0, 45.0, 120.0}) {
    CAPTURE(az);
    const Oriented o = run_view(dem, az);
    const HeightGrid slope = row_slope_map(o.z, o.frame);
    const double expected = 100 * a * std::fabs(std::sin(az * 3.14159265358979 / 180));
    for (std::size_t r = 5; r < 35; ++r)
      for (std::size_t c = 5; c < 35; ++c) REQUIRE(slope(r, c) == Approx(expected).margin(1e-3));
  }
}

TEST_CASE("the profile plot draws whole cross-sections over open ground", "[profile plot]") {
  const HeightGrid dem = make_plane(20, 30, 10, 0.3, 0.0);  // rising away: all visible
  const Oriented o = run_view(dem, 90);
  const auto lines = profile_plot(o.z, o.result.flags, o.frame, ViewParams{}, GeoTransform{}, 5,
                                  lowest_height(o.z));
  REQUIRE(lines.size() == 6);  // i = 0, 5, ..., 25
  for (const ProfileLine& line : lines) {
    CHECK(line.points.size() == 20);
    CHECK(line.distance == Approx(line.cross_section * 10.0));
    // Shifted forward (east) by (ve / B) (z - z_min) = 6.25 * 0.3 * 10 * i / 10 cells.
    const double x =
        line.cross_section + 0.5 + 6.25 * 0.3 * static_cast<double>(line.cross_section);
    for (const StrokePoint& pt : line.points) CHECK(pt.x == Approx(x));
  }
  CHECK_THROWS_AS(profile_plot(o.z, o.result.flags, o.frame, ViewParams{}, GeoTransform{}, 0, 0),
                  Error);
}

TEST_CASE("the profile plot removes hidden parts", "[profile plot]") {
  // The cliff seen from the east hides cells 20..37 behind its edge (see test_strokes).
  const HeightGrid dem = make_step(12, 40, 30.0, 20);
  const Oriented o = run_view(dem, 270);
  const auto lines = profile_plot(o.z, o.result.flags, o.frame, ViewParams{}, GeoTransform{}, 1,
                                  lowest_height(o.z));
  for (const ProfileLine& line : lines) {
    CHECK((line.cross_section < 20 || line.cross_section > 37));
    CHECK(line.points.size() == 12);
  }
  CHECK(lines.size() == 40 - 18);
}

TEST_CASE("the filter diagram counts every stage and draws the removal polygon",
          "[filter diagram]") {
  const HeightGrid dem = test::random_terrain(60, 70, 41, 0.02);
  const Oriented o = run_view(dem, 90);
  const FilterParams filter;
  const SlopeScatter s = slope_scatter(o.z, o.result.flags, o.frame.d, o.frame.w, 60.0, 60);
  std::size_t candidate = 0, filtered = 0;
  for (std::size_t k = 0; k < s.all.size(); ++k) {
    candidate += s.candidate[k], filtered += s.filtered[k];
    REQUIRE(s.candidate[k] <= s.all[k]);
    REQUIRE(s.filtered[k] <= s.candidate[k]);
  }
  CHECK(candidate == o.result.stats.candidate);
  CHECK(filtered == o.result.stats.filtered);
  // A bin whose corners all lie in the removal region holds no f-set cell.
  const double step = s.max_pct / s.bins;
  for (int r = 0; r < s.bins; ++r)
    for (int c = 0; c < s.bins; ++c) {
      bool removed = true;
      for (double dc : {0.0, 1.0})
        for (double dr : {0.0, 1.0})
          removed = removed && !filter_accepts(filter, (c + dc) * step, (r + dr) * step);
      if (removed) REQUIRE(s.filtered[static_cast<std::size_t>(r * s.bins + c)] == 0);
    }
  CHECK_THROWS_AS(slope_scatter(o.z, o.result.flags, 10, 10, 0.0), Error);
}

namespace {

// Source values that name their DEM cell: row * 1000 + col.
HeightGrid cell_ids(std::size_t rows, std::size_t cols) {
  HeightGrid g(rows, cols);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) g(r, c) = static_cast<float>(r * 1000 + c);
  return g;
}

PlanObliqueDrape drape_of(const Oriented& o) {
  return PlanObliqueDrape(o.z, o.result.flags, o.frame, ViewParams{o.frame.azimuth_deg, 2.5, 40},
                          lowest_height(o.z));
}

}  // namespace

TEST_CASE("draping over flat ground changes nothing", "[drape]") {
  const HeightGrid dem(15, 20, 100.f);
  const Oriented o = run_view(dem, 90);
  const PlanObliqueDrape drape = drape_of(o);
  REQUIRE(drape.rows() == 15);
  REQUIRE(drape.cols() == 20);
  const HeightGrid ids = cell_ids(15, 20);
  const HeightGrid out = drape.drape(ids);
  for (std::size_t k = 0; k < ids.size(); ++k) REQUIRE(out.data()[k] == ids.data()[k]);
  GeoTransform gt;
  gt.a = {1000, 10, 0, 5000, 0, -10};
  CHECK(drape.geotransform(gt).a == gt.a);
}

TEST_CASE("a slope facing the viewer is stretched by the drape", "[drape]") {
  // z rises 16 % eastwards on 10 m cells: plan-oblique position i + 6.25 * 0.16 * i = 2 i.
  HeightGrid dem(5, 30);
  for (std::size_t r = 0; r < 5; ++r)
    for (std::size_t c = 0; c < 30; ++c) dem(r, c) = static_cast<float>(0.16 * 10 * c);
  const Oriented o = run_view(dem, 90);
  const HeightGrid out = drape_of(o).drape(cell_ids(5, 30));
  REQUIRE(out.cols() == 59);
  for (std::size_t i = 0; i < 29; ++i) {
    CAPTURE(i);
    REQUIRE(out(2, 2 * i) == static_cast<float>(2000 + i));
    // Half-way between two cells: either neighbour (a tie up to rounding).
    const float between = out(2, 2 * i + 1);
    REQUIRE((between == static_cast<float>(2000 + i) || between == static_cast<float>(2001 + i)));
  }
}

TEST_CASE("hidden terrain never shows in the drape", "[drape]") {
  const HeightGrid dem = make_step(12, 40, 30.0, 20);  // seen from the east: 20..37 hidden
  const Oriented o = run_view(dem, 270);
  const HeightGrid out = drape_of(o).drape(cell_ids(12, 40));
  std::size_t shown = 0;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (!is_data(out.data()[k])) continue;
    ++shown;
    const auto col = static_cast<std::size_t>(out.data()[k]) % 1000;
    // Oriented cell i = 39 - col; hidden cells are i = 20..37, columns 2..19.
    REQUIRE((col < 2 || col > 19));
  }
  CHECK(shown > 0);
}

TEST_CASE("a drape laid out on several threads is the one laid out on one", "[drape]") {
  // Profiles and output rows are cut into many chunks: each thread's share of the extent and of
  // the rows must come together as one thread's.
  const HeightGrid dem = test::random_terrain(300, 260, 21);
  for (const double azimuth : {90.0, 135.0, 250.0}) {
    CAPTURE(azimuth);
    const Oriented o = run_view(dem, azimuth);
    const ViewParams view{azimuth, 2.5, 40};
    const PlanObliqueDrape one(o.z, o.result.flags, o.frame, view, lowest_height(o.z), {}, 1);
    const PlanObliqueDrape three(o.z, o.result.flags, o.frame, view, lowest_height(o.z), {}, 3);
    REQUIRE(one.rows() == three.rows());
    REQUIRE(one.cols() == three.cols());
    GeoTransform gt;
    gt.a = {1000, 10, 0, 5000, 0, -10};
    CHECK(one.geotransform(gt).a == three.geotransform(gt).a);
    const HeightGrid ids = cell_ids(300, 260);
    const HeightGrid a = one.drape(ids), b = three.drape(ids);
    std::size_t shown = 0;
    for (std::size_t k = 0; k < a.size(); ++k) {
      REQUIRE(std::memcmp(&a.data()[k], &b.data()[k], sizeof(float)) == 0);
      shown += is_data(a.data()[k]);
    }
    CHECK(shown > 300 * 260 / 2);
  }
}

TEST_CASE("any azimuth drapes, and a raster off the DEM grid is refused", "[drape]") {
  const HeightGrid dem = test::random_terrain(40, 50, 9);
  const Oriented o = run_view(dem, 135);
  const PlanObliqueDrape drape = drape_of(o);
  const HeightGrid out = drape.drape(dem);
  std::size_t shown = 0;
  for (std::size_t k = 0; k < out.size(); ++k) shown += is_data(out.data()[k]);
  CHECK(shown > 1000);
  CHECK_THROWS_AS(drape.drape(HeightGrid(40, 49)), Error);
}

TEST_CASE("laying out a drape reports its progress and stops when cancelled", "[drape]") {
  // A DEM of 1000 profiles: the progress is heard every 256 of them and every 256 output rows.
  const HeightGrid dem = test::random_terrain(1000, 60, 4);
  const Oriented o = run_view(dem, 90);
  const ViewParams view{90, 2.5, 40};
  std::vector<double> heard;
  const PlanObliqueDrape drape(o.z, o.result.flags, o.frame, view, lowest_height(o.z),
                               [&heard](double done) {
                                 heard.push_back(done);
                                 return true;
                               });
  REQUIRE(heard.size() >= 5);
  CHECK(std::is_sorted(heard.begin(), heard.end()));
  CHECK(heard.front() == 0.0);
  // Into the output rows. (Only the caller's thread reports, so the last report may fall short
  // of 1 when another thread finishes the last rows.)
  CHECK(heard.back() > 0.5);
  CHECK(heard.back() <= 1.0);
  int calls = 0;
  CHECK_THROWS_AS(PlanObliqueDrape(o.z, o.result.flags, o.frame, view, lowest_height(o.z),
                                   [&calls](double) { return ++calls < 3; }),
                  Cancelled);
  CHECK(calls == 3);
}
