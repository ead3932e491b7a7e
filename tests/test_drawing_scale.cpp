// Drawn strokes drawn for a map scale (issue 31, item 6): each stroke weighed by the relief it
// outlines, strokes sized on paper, and those outlining too little relief for the scale dropped.
#include <cmath>
#include <vector>

#include "catch_compat.h"
#include "core/drawn/drawing_scale.h"
#include "core/drawn/drawn_strokes.h"
#include "core/method/orient.h"
#include "core/method/silhouettes.h"

using namespace tsk;

namespace {

// The weight of a stroke outlining `relief`, as documented: 0.4 up to a thirtieth of the full
// relief, rising with its logarithm to 1 at the full relief.
double documented_weight(double relief, double full) {
  const double least = full / 30.0;
  if (relief <= least) return 0.4;
  return 0.4 + 0.6 * std::min(1.0, std::log(relief / least) / std::log(30.0));
}

// Two ridges running north-south on flat ground, 10 m cells: a low one (8 m, but steep enough to
// hide ground) at column 25 and a tall one (150 m) at column 100, behind it from the west.
HeightGrid two_ridges() {
  HeightGrid dem(100, 160);
  for (std::size_t r = 0; r < dem.rows(); ++r) {
    for (std::size_t c = 0; c < dem.cols(); ++c) {
      const double a = (static_cast<double>(c) - 100.0) / 8.0,
                   b = (static_cast<double>(c) - 25.0) / 2.0;
      dem(r, c) =
          static_cast<float>(100.0 + 150.0 * std::exp(-a * a / 2) + 8.0 * std::exp(-b * b / 2));
    }
  }
  return dem;
}

// The drawn strokes of two_ridges() seen from the west, on a 10 m grid in map units.
SilhouetteResult sketch_ridges(double scale) {
  const HeightGrid dem = two_ridges();
  SilhouetteParams params;
  params.view.azimuth_deg = 90;
  params.strokes.mode = StrokeMode::drawn;
  params.strokes.depth_cue = 0.0;  // the weights are the taper and the relief only
  params.strokes.scale = scale;
  const OrientedFrame frame = make_frame(dem.rows(), dem.cols(), 10, 10, 90);
  GeoTransform gt;
  gt.a = {0.0, 10.0, 0.0, 1000.0, 0.0, -10.0};
  return run_silhouettes(orient(dem, frame), frame, gt, ResolvedParams(params));
}

// The factual strokes whose mean x lies within 15 cells of column `column`.
std::vector<const Stroke*> factual_near(const SilhouetteResult& r, double column) {
  std::vector<const Stroke*> found;
  for (const Stroke& s : r.strokes) {
    if (s.cls != StrokeClass::factual) continue;
    double x = 0;
    for (const StrokePoint& p : s.points) x += p.x;
    x /= static_cast<double>(s.points.size());
    if (std::fabs(x / 10.0 - column) < 15.0) found.push_back(&s);
  }
  return found;
}

double heaviest(const Stroke& s) {
  double most = 0;
  for (double w : s.weights) most = std::max(most, w);
  return most;
}

}  // namespace

TEST_CASE("relief weighs a stroke from the least weight to full on a log scale", "[drawn][scale]") {
  for (double relief : {0.0, 1.0, 3.0, 10.0, 33.3, 50.0, 99.0, 100.0, 500.0})
    CHECK(relief_weight(relief, 100.0) == Approx(documented_weight(relief, 100.0)));
  CHECK(relief_weight(100.0 / std::sqrt(30.0), 100.0) == Approx(0.7));
  CHECK(relief_weight(std::nan(""), 100.0) == Approx(0.4));
  CHECK(relief_weight(5.0, 0.0) == 1.0);
  // A factual stroke outlines the height it hides; a formulated one its slope over its length.
  Stroke factual;
  factual.max_depth_m = 42.0;
  CHECK(stroke_relief(factual) == 42.0);
  Stroke formulated;
  formulated.cls = StrokeClass::formulated;
  formulated.mean_slope_pct = 20.0;
  formulated.length = 500.0;
  formulated.max_depth_m = std::nan("");
  CHECK(stroke_relief(formulated) == Approx(100.0));
}

TEST_CASE("a scale sizes the drawn strokes on paper and never below their own settings",
          "[drawn][scale]") {
  DrawingSetup setup;
  setup.cell = 75.0;  // metres
  // 1:1 000 000 on 75 m cells: 0.75 mm joins 750 m (10 cells), 0.5 mm smooths 500 m (6.67
  // cells), 0.4 mm of tolerance is 5.33 cells (at most 5), and 2 mm keeps strokes of 27 cells.
  setup.drawn.scale = 1e6;
  fit_to_scale(setup);
  CHECK(setup.drawn.join_gap_cells == Approx(10.0));
  CHECK(setup.drawn.smooth_cells == Approx(500.0 / 75.0));
  CHECK(setup.drawn.tolerance_cells == Approx(5.0));
  CHECK(setup.min_cells == 27);
  CHECK(setup.relief_full == Approx(1000.0));
  CHECK(setup.relief_vanishing == Approx(100.0));
  // 1:50 000 asks less than the defaults: they stay.
  DrawingSetup fine;
  fine.cell = 75.0;
  fine.drawn.scale = 50000;
  fit_to_scale(fine);
  const DrawnParams defaults;
  CHECK(fine.drawn.join_gap_cells == defaults.join_gap_cells);
  CHECK(fine.drawn.smooth_cells == defaults.smooth_cells);
  CHECK(fine.drawn.tolerance_cells == defaults.tolerance_cells);
  CHECK(fine.min_cells == 3);
  CHECK(fine.relief_full == Approx(50.0));
  // No scale: nothing changes but the relief weights, which follow the DEM's own scale (1:2500
  // per metre of cell: 187.5 m of relief at full weight on 75 m cells), and nothing vanishes.
  DrawingSetup own;
  own.cell = 75.0;
  fit_to_scale(own);
  CHECK(own.drawn.join_gap_cells == defaults.join_gap_cells);
  CHECK(own.min_cells == 3);
  CHECK(own.relief_full == Approx(187.5));
  CHECK(own.relief_vanishing == 0.0);
}

TEST_CASE("a tall ridge outweighs a low one, which vanishes at a small scale", "[drawn][scale]") {
  const SilhouetteResult own = sketch_ridges(0.0);
  const std::vector<const Stroke*> tall = factual_near(own, 100), low = factual_near(own, 25);
  REQUIRE(!tall.empty());
  REQUIRE(!low.empty());
  // Each stroke's heaviest point (the taper's middle) weighs what its relief does: 25 m of relief
  // at full weight on a 10 m grid.
  for (const Stroke* s : tall)
    CHECK(heaviest(*s) == Approx(documented_weight(s->max_depth_m, 25.0)).margin(1e-9));
  for (const Stroke* s : low) {
    CHECK(heaviest(*s) == Approx(documented_weight(s->max_depth_m, 25.0)).margin(1e-9));
    CHECK(s->max_depth_m < 8.0);
    CHECK(heaviest(*s) < heaviest(*tall.front()));
  }
  CHECK(heaviest(*tall.front()) == Approx(1.0));
  // At 1:100 000 the low ridge hides less than the 10 m that matter: its strokes vanish, the tall
  // one's stay (as long as 2 mm on paper: 20 cells).
  const SilhouetteResult small = sketch_ridges(100000);
  CHECK(factual_near(small, 25).empty());
  REQUIRE(!factual_near(small, 100).empty());
  for (const Stroke& s : small.strokes) CHECK(s.cells >= 20);
}
