#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// A cliff running north-south, seen from the east so its edge occludes: 12 profiles, one
// straight factual stroke along column 20 (the top edge, last high column seen from the east).
struct Cliff {
  HeightGrid dem = make_step(12, 40, 30.0, 20);  // high from column 20 eastwards
  SilhouetteParams params;
  Cliff() { params.view.azimuth_deg = 270; }
};

}  // namespace

TEST_CASE("a cliff edge becomes one factual stroke with its attributes", "[strokes]") {
  Cliff c;
  const SilhouetteResult r = test::run_on_dem(c.dem, c.params, 10, 10);
  REQUIRE(r.stats.factual_strokes == 1);
  REQUIRE(r.stats.formulated_strokes == 0);
  const Stroke& s = r.strokes[0];
  CHECK(s.cls == StrokeClass::factual);
  CHECK(s.cells == 12);
  REQUIRE(s.points.size() == 12);
  for (const StrokePoint& pt : s.points) CHECK(pt.x == Approx(20.5));  // pixel coordinates
  CHECK(s.length == Approx(11.0));  // identity georeferencing: 11 cells between centres
  // Depth: 30 m high edge, first hidden cell one 10 m step behind: (2.5*30 - 0.4*10) / 2.5.
  CHECK(s.mean_depth_m == Approx(28.4));
  CHECK(s.max_depth_m == Approx(28.4));
  // Column slope at the edge, seen from the east: 30 m drop over 10 m = 300 %.
  CHECK(s.mean_slope_pct == Approx(300.0));
  CHECK(s.mean_row_slope_pct == Approx(0.0));
  CHECK(s.mean_dist == Approx(19 * 10.0));  // oriented cell 19 from the east edge
  CHECK(s.mean_z == Approx(30.0));
}

TEST_CASE("plan-oblique geometry moves points along the azimuth by (ve / B)(z - z_ref)",
          "[strokes]") {
  Cliff c;
  c.params.geometry = Geometry::oblique;
  const double cell = 10;
  const SilhouetteResult r = test::run_on_dem(c.dem, c.params, cell, cell);
  REQUIRE(r.strokes.size() == 1);
  // Facing west: moves west by 2.5 / 0.4 * 30 m = 187.5 m = 18.75 cells (pixel units here).
  for (const StrokePoint& pt : r.strokes[0].points) CHECK(pt.x == Approx(20.5 - 18.75));
  CHECK(r.strokes[0].length == Approx(11.0));  // length stays the ground length
}

TEST_CASE("formulated strokes have no depth", "[strokes]") {
  const SilhouetteResult r = test::run_on_dem(test::random_terrain(60, 60, 21), SilhouetteParams{});
  REQUIRE(r.stats.formulated_strokes > 0);
  for (const Stroke& s : r.strokes) {
    if (s.cls == StrokeClass::formulated) {
      CHECK(std::isnan(s.mean_depth_m));
      CHECK(std::isnan(s.max_depth_m));
    } else {
      CHECK(s.mean_depth_m > 0);
    }
  }
}

TEST_CASE("sub-cell placement finds the parabola peak within half a cell", "[strokes]") {
  const ViewParams view;
  // A skewed peak moves towards its higher neighbour.
  const float symmetric[] = {0, 8, 10, 8, 0};
  // t = 24, 33, 32 around cell 2 (the base slope tilts the peak away from the viewer):
  // vertex at 2 + 0.5 (24 - 32) / (24 - 66 + 32) = 2.4.
  CHECK(subcell_peak(symmetric, 5, 2, 10, view) == Approx(2.4));
  const float skewed[] = {0, 9, 10, 2, 0};
  const double at = subcell_peak(skewed, 5, 2, 10, view);
  CHECK(at < 2.0);
  CHECK(at >= 1.5);
  const float edge[] = {10, 2};
  CHECK(subcell_peak(edge, 2, 0, 10, view) == 0.0);
}

TEST_CASE("a stroke builder reused after clear() builds as a fresh one does", "[strokes]") {
  const auto cell = [](int p, double x, double slope, double depth) {
    StrokeCell c;
    c.cell = {p, 3};
    c.map = c.point = {x, 0.0};
    c.dist = 30.0, c.slope_pct = slope, c.row_slope_pct = 1.0, c.depth_m = depth, c.z = 100.0 + p;
    return c;
  };
  StrokeBuilder reused;
  for (int p = 0; p < 4; ++p) reused.add(cell(p, 7.0 * p, 50.0 + p, 9.0 + p));
  CHECK(reused.stroke(StrokeClass::factual).max_depth_m == Approx(12.0));
  reused.clear();
  StrokeBuilder fresh;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Three cells in a right angle (lengths 3 and 4), one slope unknown.
  for (StrokeBuilder* b : {&reused, &fresh}) {
    b->add(cell(0, 0.0, 20.0, 2.0));
    b->add(cell(1, 3.0, nan, 6.0));
    StrokeCell last = cell(1, 3.0, 40.0, 4.0);
    last.cell.p = 2, last.map.y = 4.0;
    b->add(last);
  }
  const Stroke a = reused.stroke(StrokeClass::factual), b = fresh.stroke(StrokeClass::factual);
  CHECK(a.cells == 3);
  CHECK(a.chain.size() == 3);
  CHECK(a.points.size() == 3);
  CHECK(a.length == Approx(3.0 + 4.0));
  CHECK(a.mean_slope_pct == Approx(30.0));  // the unknown slope left out
  CHECK(a.mean_depth_m == Approx(4.0));
  CHECK(a.max_depth_m == Approx(6.0));
  for (double Stroke::*m :
       {&Stroke::length, &Stroke::mean_slope_pct, &Stroke::mean_row_slope_pct,
        &Stroke::mean_depth_m, &Stroke::max_depth_m, &Stroke::mean_dist, &Stroke::mean_z}) {
    CHECK(a.*m == b.*m);
  }
  const Stroke formulated = fresh.stroke(StrokeClass::formulated);
  CHECK(std::isnan(formulated.mean_depth_m));
  CHECK(std::isnan(formulated.max_depth_m));
  CHECK(formulated.mean_slope_pct == Approx(30.0));
}
