#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

HeightGrid numbered(std::size_t rows, std::size_t cols) {
  HeightGrid g(rows, cols);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) g(r, c) = static_cast<float>(r * 100 + c);
  return g;
}

}  // namespace

TEST_CASE("orientation puts the nearest cell of the leftmost profile first", "[orient]") {
  const HeightGrid dem = numbered(3, 5);  // row 0 north, column 0 west
  struct Case {
    double azimuth;
    float front_left, front_right, back_left;
    std::size_t profiles;
  };
  // Viewer facing east (from the west): left is north, front is west.
  // Facing north: left is west, front is south. Facing south: left east, front north.
  // Facing west: left south, front east.
  const Case cases[] = {
      {90, 0, 200, 4, 3}, {0, 200, 204, 0, 5}, {180, 4, 0, 204, 5}, {270, 204, 4, 200, 3}};
  for (const Case& c : cases) {
    CAPTURE(c.azimuth);
    const OrientedFrame f = make_frame(3, 5, 10, 20, c.azimuth);
    const HeightGrid g = orient(dem, f);
    REQUIRE(g.rows() == c.profiles);
    CHECK(g(0, 0) == c.front_left);
    CHECK(g(g.rows() - 1, 0) == c.front_right);
    CHECK(g(0, g.cols() - 1) == c.back_left);
    for (std::size_t p = 0; p < g.rows(); ++p)
      for (std::size_t i = 0; i < g.cols(); ++i) {
        REQUIRE(g(p, i) == dem(f.dem_row(p, i), f.dem_col(p, i)));
        const PixelPoint px = f.to_pixel(static_cast<double>(p), static_cast<double>(i));
        REQUIRE(px.col == Approx(f.dem_col(p, i) + 0.5));
        REQUIRE(px.row == Approx(f.dem_row(p, i) + 0.5));
      }
  }
}

TEST_CASE("spacings follow the line of sight on non-square cells", "[orient]") {
  const OrientedFrame east = make_frame(3, 5, 10, 20, 90);
  CHECK(east.d == 10);
  CHECK(east.w == 20);
  const OrientedFrame north = make_frame(3, 5, 10, 20, 0);
  CHECK(north.d == 20);
  CHECK(north.w == 10);
  CHECK(make_frame(3, 5, 10, 20, -90).azimuth_deg == 270);
  CHECK(make_frame(3, 5, 10, 20, 360).azimuth_deg == 0);
}

TEST_CASE("orientation refuses empty grids, bad cell sizes and huge sizes", "[orient]") {
  CHECK_THROWS_AS(make_frame(0, 5, 10, 10, 90), Error);
  CHECK_THROWS_AS(make_frame(3, 5, 0, 10, 90), Error);
  CHECK_THROWS_AS(make_frame(3, 5, 10, std::nan(""), 90), Error);
  CHECK_THROWS_AS(make_frame(3, 5, -1, 10, 90), Error);
  // Cells beyond any terrain's, whose squares leave the doubles' range; the bounds themselves
  // pass.
  for (const double cell : {1e-300, 1e-13, 1e13, 1e300})
    CHECK_THROWS_WITH(make_frame(3, 5, cell, 10, 90), Catch::Contains("beyond any terrain's"));
  CHECK_THROWS_WITH(make_frame(3, 5, 10, 1e-20, 45), Catch::Contains("beyond any terrain's"));
  CHECK_NOTHROW(make_frame(3, 5, 1e-12, 1e12, 90));
  CHECK_THROWS_AS(make_frame(std::size_t{1} << 32, 5, 10, 10, 90), Error);
  CHECK_THROWS_AS(checked_cell_count(std::size_t{1} << 31, std::size_t{1} << 31), Error);
}

TEST_CASE("a grid reshaped smaller keeps its memory, larger takes new", "[orient]") {
  HeightGrid strip(4, 6, 1.0f);
  const float* memory = strip.data();
  strip.reshape(3, 5, kUnset);
  CHECK(strip.rows() == 3);
  CHECK(strip.cols() == 5);
  CHECK(strip.size() == 15);
  CHECK(strip.data() == memory);
  strip.reshape(5, 6, kUnset);
  CHECK(strip.size() == 30);
  CHECK(strip.row(4) == strip.data() + 24);
  CHECK_THROWS_AS(strip.reshape(std::size_t{1} << 31, std::size_t{1} << 31, kUnset), Error);
  CHECK(strip.size() == 30);
}

TEST_CASE("a DEM read block by block equals one turned at once", "[orient]") {
  const HeightGrid dem = numbered(7, 4);
  for (double az : {0.0, 90.0, 180.0, 270.0}) {
    const OrientedFrame f = make_frame(7, 4, 1, 1, az);
    HeightGrid blocks(f.profiles, f.length);
    scatter_dem_rows(f, 0, 3, dem.row(0), 4, blocks);
    scatter_dem_rows(f, 3, 4, dem.row(3), 4, blocks);
    const HeightGrid whole = orient(dem, f);
    CHECK(std::equal(whole.data(), whole.data() + whole.size(), blocks.data()));
    CHECK_THROWS_AS(scatter_dem_rows(f, 5, 4, dem.row(0), 4, blocks), Error);
  }
}

TEST_CASE("the plan-oblique reference is the DEM's lowest height, not the resampled grid's",
          "[orient]") {
  // A one-cell pit: bilinear samples between cell centres never reach its bottom.
  HeightGrid dem(20, 20, 100.f);
  dem(9, 9) = 40.f;
  dem(0, 0) = kNoData;
  for (double az : {90.0, 45.0}) {
    CAPTURE(az);
    const OrientedFrame f = make_frame(20, 20, 10, 10, az);
    OrientedGridBuilder builder(f);
    builder.add_rows(0, 12, dem.row(0));
    builder.add_rows(12, 8, dem.row(12));
    CHECK(builder.dem_lowest_height() == 40.0);
    const HeightGrid oriented = builder.finish();
    if (f.resampled) {
      CHECK(lowest_height(oriented) > 40.0);
    } else {
      CHECK(lowest_height(oriented) == 40.0);
    }
  }
  OrientedGridBuilder empty(make_frame(2, 2, 1, 1, 90));
  CHECK(empty.dem_lowest_height() == 0.0);
}
