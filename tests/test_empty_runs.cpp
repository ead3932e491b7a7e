// A run that draws no stroke says so, with the stage that left nothing and what to change: the
// user is never handed empty layers without a word.
#include "catch_compat.h"
#include "cli_run.h"
#include "gdal_test_support.h"

using namespace tsk;
using namespace tsk::test;

namespace {

constexpr const char* kNoStrokes = "warning: no strokes: ";

// 60 x 60 cells of 10 m falling `drop` m a cell towards the east, away from a viewer facing east
// (azimuth 90): every cell slopes away at drop / 10, and none hides another.
void write_plane(const std::string& path, float drop) {
  write_tiff(
      path, 60, 60, 1, [drop](int, int, int c) { return 1000.0f - drop * static_cast<float>(c); },
      kNorthUp, 32616);
}

}  // namespace

TEST_CASE("a run that draws no stroke says which stage left nothing, and what to change",
          "[cli][robustness]") {
  ScratchDir dir("empty_runs");
  SECTION("a flat DEM: nothing hidden, nothing seen edge-on") {
    write_plane(dir / "flat.tif", 0.0f);
    const auto run = run_cli({"silhouettes", dir / "flat.tif", dir / "flat.gpkg"});
    CHECK(run.code == 0);
    CHECK_THAT(run.out, Catch::Contains("0 factual and 0 formulated strokes"));
    CHECK_THAT(run.err, Catch::Contains(std::string(kNoStrokes) + "no cell of the DEM is hidden"));
    // The band of back slopes a tilted view shows: base slope over exaggeration, 40 / 2.5.
    CHECK_THAT(run.err, Catch::Contains("16 %"));
  }
  SECTION("every cell nodata, declared or NaN: said so, not called flat") {
    write_tiff(
        dir / "declared.tif", 60, 60, 1, [](int, int, int) { return -9999.0f; }, kNorthUp, 32616,
        -9999.0);
    write_tiff(
        dir / "nan.tif", 60, 60, 1, [](int, int, int) { return NAN; }, kNorthUp, 32616);
    for (const char* name : {"declared", "nan"}) {
      CAPTURE(name);
      const auto run = run_cli(
          {"silhouettes", dir / (std::string(name) + ".tif"), dir / (std::string(name) + ".gpkg")});
      CHECK(run.code == 0);
      CHECK_THAT(run.err,
                 Catch::Contains(std::string(kNoStrokes) + "every cell of the DEM is nodata"));
      CHECK(run.err.find("faces the viewer") == std::string::npos);
    }
  }
  SECTION("a plane sloping away at 5 %: every cell a candidate, the thesis's filter removes all") {
    write_plane(dir / "plane.tif", 0.5f);
    const auto fixed =
        run_cli({"silhouettes", dir / "plane.tif", dir / "fixed.gpkg", "--filter", "fixed"});
    CHECK(fixed.code == 0);
    CHECK_THAT(fixed.out, Catch::Contains("0 factual and 0 formulated strokes"));
    CHECK_THAT(fixed.err, Catch::Contains(std::string(kNoStrokes) +
                                          "the slope filter removed every candidate"));
    CHECK_THAT(fixed.err, Catch::Contains("or --filter adaptive scales them"));
    // Scaled to the plane's own slope, the adaptive filter keeps its far edge: strokes, no warning.
    const auto adaptive = run_cli({"silhouettes", dir / "plane.tif", dir / "adaptive.gpkg"});
    CHECK(adaptive.code == 0);
    CHECK(adaptive.out.find("0 factual and 0 formulated") == std::string::npos);
    CHECK(adaptive.err.find(kNoStrokes) == std::string::npos);
  }
  SECTION("a real DEM whose chains are all shorter than the shortest stroke kept") {
    const auto run = run_cli({"silhouettes", TSK_SAMPLE_DEM, dir / "short.gpkg", "--strokes",
                              "exact", "--min-cells", "5000"});
    CHECK(run.code == 0);
    CHECK_THAT(run.err, Catch::Contains(std::string(kNoStrokes) + "every chain was shorter than "
                                                                  "the shortest stroke kept "
                                                                  "(--min-cells 5000)"));
    const auto coarse =
        run_cli({"silhouettes", TSK_SAMPLE_DEM, dir / "coarse.gpkg", "--drawn-for", "1000000000"});
    CHECK(coarse.code == 0);
    CHECK_THAT(coarse.err, Catch::Contains("drawn for 1:1000000000, strokes under 2 mm on paper, "
                                           "or outlining under 100000 m of relief"));
    // The defaults on the same DEM draw strokes, and warn of nothing.
    const auto defaults = run_cli({"silhouettes", TSK_SAMPLE_DEM, dir / "defaults.gpkg"});
    CHECK(defaults.code == 0);
    CHECK(defaults.err.find("warning") == std::string::npos);
  }
}
