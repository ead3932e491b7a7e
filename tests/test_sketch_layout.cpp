// The preview's page laid out stroke by stroke: where a drawn stroke's point lands, worked out
// independently through an exact stroke's cell, and the run's reference height applied when the
// page is taken.
#include <cmath>

#include "catch_compat.h"
#include "io/pages/sketch_page.h"

namespace {

using tsk::ChainCell;
using tsk::Geometry;
using tsk::Stroke;
using tsk::StrokeClass;
using tsk::StrokePoint;

constexpr float kHeight = 250.0f;  // flat ground: every cell, and the DEM's lowest height

struct FlatView {
  tsk::HeightGrid z{30, 40, kHeight};  // oriented: from the west, profiles are the DEM's rows
  tsk::OrientedFrame frame = tsk::make_frame(30, 40, 10.0, 10.0, 90.0);
  tsk::GeoTransform geotransform;
  tsk::ViewParams view{90.0, 2.5, 40.0};
  FlatView() { geotransform.a = {1000, 10, 0, 5000, 0, -10}; }

  // The map place of the centre of oriented cell (p, i).
  StrokePoint centre(int p, int i) const {
    StrokePoint at{};
    geotransform.apply(frame.to_pixel(p, i), at.x, at.y);
    return at;
  }
  tsk::io::SketchPage page(const Stroke& stroke, Geometry geometry, double z_ref) const {
    tsk::io::SketchLayout layout(z, frame, geotransform, view, geometry, tsk::io::PageOptions{});
    layout.add(stroke);
    return layout.take_page(z_ref);
  }
};

const ChainCell kCells[] = {{4, 7}, {5, 9}, {6, 12}, {7, 30}};

Stroke exact_stroke() {
  Stroke s;
  s.cls = StrokeClass::formulated;
  for (const ChainCell& c : kCells) s.chain.push_back(c);
  return s;
}

// A drawn stroke through the same cells' centres (unshifted: on flat ground at the run's
// reference height, plan-oblique points are where the map's are).
Stroke drawn_stroke(const FlatView& v) {
  Stroke s;
  s.cls = StrokeClass::formulated;
  for (const ChainCell& c : kCells) {
    s.points.push_back(v.centre(c.p, c.i));
    s.weights.push_back(0.5);
  }
  return s;
}

}  // namespace

TEST_CASE("a drawn stroke's points land where an exact stroke's cells do", "[preview]") {
  const FlatView v;
  const auto exact = v.page(exact_stroke(), Geometry::map, kHeight);
  REQUIRE(exact.paths.size() == 1);
  REQUIRE(exact.paths[0].points.size() == 4);
  for (const Geometry geometry : {Geometry::map, Geometry::oblique}) {
    const auto drawn = v.page(drawn_stroke(v), geometry, kHeight);
    REQUIRE(drawn.paths.size() == 1);
    REQUIRE(drawn.width == exact.width);
    REQUIRE(drawn.height == exact.height);
    for (std::size_t k = 0; k < 4; ++k) {
      CAPTURE(k);
      CHECK(std::abs(drawn.paths[0].points[k].x - exact.paths[0].points[k].x) < 1e-9);
      CHECK(std::abs(drawn.paths[0].points[k].y - exact.paths[0].points[k].y) < 1e-9);
    }
  }
}

TEST_CASE("plan-oblique points are lifted by the run's reference height when the page is taken",
          "[preview]") {
  const FlatView v;
  const Stroke stroke = drawn_stroke(v);
  const auto level = v.page(stroke, Geometry::oblique, kHeight);
  const auto lower = v.page(stroke, Geometry::oblique, kHeight - 10.0);
  // Shifted from 10 m lower, a point stands k * 10 cells nearer the viewer than it was drawn:
  // k = ve / (base slope * d) cells a metre, d = 10 m, and the page's pixels a metre across the
  // 300 m of profiles between the 10-pixel margins of the 1600-pixel picture.
  const double cells = 2.5 / (0.40 * 10.0) * 10.0;
  const double pixels_per_metre = (1600.0 - 20.0) / 300.0;
  for (std::size_t k = 0; k < 4; ++k) {
    CAPTURE(k);
    CHECK(lower.paths[0].points[k].x == level.paths[0].points[k].x);
    CHECK(std::abs(lower.paths[0].points[k].y - level.paths[0].points[k].y -
                   cells * 10.0 * pixels_per_metre) < 1e-9);
  }
  // In map geometry the reference changes nothing: the points were never shifted.
  const auto map_level = v.page(stroke, Geometry::map, kHeight);
  const auto map_lower = v.page(stroke, Geometry::map, kHeight - 10.0);
  for (std::size_t k = 0; k < 4; ++k)
    CHECK(map_lower.paths[0].points[k].y == map_level.paths[0].points[k].y);
}

TEST_CASE("a drawn point past the edge of nodata takes the nearest height, not the lowest",
          "[preview]") {
  // A drawn point may lie within its tolerance of its cell on a nodata cell beside it. The
  // oriented grid: columns from kEdge on are nodata; a ridge of kRidge metres runs along the
  // columns before them, far from the DEM's lowest ground (kHeight, columns 0 to 4).
  constexpr int kEdge = 20;
  constexpr float kRidge = 400.0f;
  FlatView past_edge;
  for (std::size_t p = 0; p < past_edge.z.rows(); ++p) {
    for (std::size_t i = 5; i < past_edge.z.cols(); ++i)
      past_edge.z(p, i) = i < kEdge ? kRidge : tsk::kNoData;
  }
  // The same DEM with the ridge's height on the point's own cell too (the same lowest and highest
  // heights, so the same page): there the point is where it should be on the nodata one.
  FlatView ridge_under = past_edge;
  const int p = 12;
  ridge_under.z(p, kEdge) = kRidge;

  Stroke stroke;
  stroke.cls = StrokeClass::factual;
  for (const int i : {kEdge - 2, kEdge - 1, kEdge}) {
    stroke.points.push_back(past_edge.centre(p, i));
    stroke.weights.push_back(0.5);
  }
  const auto on_nodata = past_edge.page(stroke, Geometry::map, kHeight);
  const auto expected = ridge_under.page(stroke, Geometry::map, kHeight);
  REQUIRE(on_nodata.height == expected.height);
  for (std::size_t k = 0; k < 3; ++k) {
    CAPTURE(k);
    CHECK(std::abs(on_nodata.paths[0].points[k].x - expected.paths[0].points[k].x) < 1e-9);
    CHECK(std::abs(on_nodata.paths[0].points[k].y - expected.paths[0].points[k].y) < 1e-9);
  }
}
