// The P-stroke algorithm against the core.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the P-stroke algorithm draws the core's P-strokes", "[plugin][pstrokes]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  // The thesis's filter, which the core runs by default.
  const Run run = runOk(dem, {{"GEOMETRY", 0}, {"FILTER", 1}, {"OUTPUT", dir.filePath("p.gpkg")}},
                        dir, QStringLiteral("pstrokes"));
  const io::Dem core = coreDem(dem);
  const SilhouetteResult result = run_silhouettes(core.oriented, core.frame, core.geotransform, {});
  const auto expected =
      pstroke_sketch(core.oriented, result.flags, core.frame, ViewParams{}, core.geotransform,
                     Geometry::map, PStrokeParams{}, core.lowest_height);
  QgsVectorLayer layer(run.results.value("OUTPUT").toString(), "p", "ogr");
  REQUIRE(layer.isValid());
  CHECK(layer.featureCount() == static_cast<long long>(expected.size()));
  CHECK(layer.fields().indexOf("score_m2") >= 0);
  const Run bad = runAlgorithm(dem, {{"HALF_LENGTH", 0}, {"OUTPUT", dir.filePath("q.gpkg")}}, dir,
                               nullptr, QStringLiteral("pstrokes"));
  CHECK_FALSE(bad.ok);
}
