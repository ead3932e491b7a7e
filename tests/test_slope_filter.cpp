#include <random>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// The oracle: ray casting against the removal polygon (0,0) (col_cut,0) ctrl (0,row_cut).
bool inside_removal_polygon(const FilterParams& f, double c, double r) {
  const double xs[] = {0, f.col_cut_pct, f.ctrl_col_pct, 0};
  const double ys[] = {0, 0, f.ctrl_row_pct(), f.row_cut_pct};
  bool inside = false;
  for (int k = 0, j = 3; k < 4; j = k++) {
    if ((ys[k] > r) != (ys[j] > r) && c < (xs[j] - xs[k]) * (r - ys[k]) / (ys[j] - ys[k]) + xs[k]) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

TEST_CASE("the control point lies on the perpendicular through the origin", "[filter]") {
  const FilterParams f;
  CHECK(f.ctrl_row_pct() == Approx(5.25));
  // Perpendicular to the line joining the cut-offs (col_cut, 0) -> (0, row_cut).
  const double dot = f.ctrl_col_pct * (0 - f.col_cut_pct) + f.ctrl_row_pct() * (f.row_cut_pct - 0);
  CHECK(dot == Approx(0).margin(1e-12));
  FilterParams g;
  g.ctrl_col_pct = 6;
  CHECK(g.ctrl_row_pct() == Approx(3.6));
}

TEST_CASE("points inside the removal polygon are removed, outside kept", "[filter]") {
  const FilterParams f;
  // Inside: the weak/weak corner, near each cut-off, and just inside the control point.
  for (auto [c, r] : {std::pair{2.0, 2.0}, {1.0, 18.0}, {11.0, 0.5}, {8.0, 5.0}, {0.0, 0.0}}) {
    CAPTURE(c, r);
    CHECK_FALSE(filter_accepts(f, c, r));
  }
  // Outside: strong row slope, strong column slope, and diagonals past the control point.
  for (auto [c, r] : {std::pair{0.0, 21.0}, {13.0, 0.1}, {5.0, 15.0}, {9.0, 6.0}, {30.0, 30.0}}) {
    CAPTURE(c, r);
    CHECK(filter_accepts(f, c, r));
  }
  // The control point itself is on the boundary, which is removed.
  CHECK_FALSE(filter_accepts(f, f.ctrl_col_pct, f.ctrl_row_pct()));
  CHECK(filter_accepts(f, f.ctrl_col_pct + 0.01, f.ctrl_row_pct() + 0.01));
}

TEST_CASE("the filter agrees with a point-in-polygon oracle", "[filter][oracle]") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 30.0);
  for (double ctrl : {8.75, 6.0, 3.0}) {
    FilterParams f;
    f.ctrl_col_pct = ctrl;
    for (int k = 0; k < 20000; ++k) {
      const double c = u(rng), r = u(rng);
      CAPTURE(ctrl, c, r);
      REQUIRE(filter_accepts(f, c, r) == !inside_removal_polygon(f, c, r));
    }
  }
}

TEST_CASE("without diagonals the removed region is the rectangle of the cut-offs", "[filter]") {
  FilterParams f;
  f.diagonals = false;
  CHECK_FALSE(filter_accepts(f, 11.9, 19.9));
  CHECK_FALSE(filter_accepts(f, 9.0, 6.0));  // kept with diagonals, removed here
  CHECK(filter_accepts(f, 12.0, 0.0));
  CHECK(filter_accepts(f, 0.0, 20.0));
  CHECK(filter_accepts(f, 40.0, 1.0));
}

TEST_CASE("row slope: central, one-sided at edges and next to nodata, flat when alone",
          "[filter]") {
  HeightGrid z(3, 2);
  z(0, 0) = 10, z(1, 0) = 14, z(2, 0) = 30;
  z(0, 1) = kNoData, z(1, 1) = 14, z(2, 1) = 30;
  CHECK(row_slope(z, 1, 0, 10) == Approx(1.0));  // (30 - 10) / 20
  CHECK(row_slope(z, 0, 0, 10) == Approx(0.4));  // (14 - 10) / 10
  CHECK(row_slope(z, 2, 0, 10) == Approx(1.6));  // (30 - 14) / 10
  CHECK(row_slope(z, 1, 1, 10) == Approx(1.6));  // left neighbour is nodata
  CHECK(std::isnan(row_slope(z, 0, 1, 10)));
  HeightGrid one(1, 3, 5.f);
  CHECK(row_slope(one, 0, 1, 10) == 0.0);
}

TEST_CASE("the f-set holds only visible, accepted c-set cells", "[filter]") {
  const HeightGrid z = test::random_terrain(60, 80, 11, 0.02);
  const ViewParams view;
  const FilterParams filter;
  CellFlags flags;
  classify_visibility(z, 10, view, flags);
  select_candidates(z, 10, view, flags);
  apply_slope_filter(z, 10, 12, filter, flags);
  std::size_t kept = 0;
  for (std::size_t p = 0; p < z.rows(); ++p)
    for (std::size_t i = 0; i < z.cols(); ++i) {
      const std::uint8_t f = flags(p, i);
      const bool expected =
          (f & cell::candidate) && !(f & cell::hidden) &&
          filter_accepts(filter, std::fabs(column_slope(z.row(p), z.cols(), i, 10)) * 100,
                         std::fabs(row_slope(z, p, i, 12)) * 100);
      REQUIRE(bool(f & cell::filtered) == expected);
      kept += expected;
    }
  CHECK(kept > 0);
}

TEST_CASE("parameters out of range are refused with a message", "[filter][params]") {
  FilterParams f;
  f.ctrl_col_pct = 12;
  CHECK_THROWS_WITH(f.validate(), Catch::Contains("control point"));
  f.ctrl_col_pct = 0;
  CHECK_THROWS_AS(f.validate(), Error);
  f = FilterParams{};
  f.row_cut_pct = std::nan("");
  CHECK_THROWS_AS(f.validate(), Error);
  ViewParams v;
  v.ve = 0;
  CHECK_THROWS_WITH(v.validate(), Catch::Contains("exaggeration"));
  // Numbers are written as people write them, not as 0.000000.
  CHECK_THROWS_WITH(v.validate(), Catch::EndsWith("got 0"));
  v = ViewParams{};
  v.azimuth_deg = 400.5;
  CHECK_THROWS_WITH(v.validate(), Catch::EndsWith("between -360 and 360, got 400.5"));
  v = ViewParams{};
  v.base_slope_pct = -1;
  CHECK_THROWS_AS(v.validate(), Error);
  ChainParams c;
  c.min_cells = 1;
  CHECK_THROWS_AS(c.validate(), Error);
  c = ChainParams{};
  c.window = -1;
  CHECK_THROWS_AS(c.validate(), Error);
}
