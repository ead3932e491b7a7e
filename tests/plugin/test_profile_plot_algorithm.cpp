// The profile plot algorithm against the core.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the profile plot algorithm draws the core's lines", "[plugin][profile plot]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runOk(dem, {{"EVERY", 12}}, dir, QStringLiteral("profileplot"));
  const io::Dem core = coreDem(dem);
  CellFlags flags;
  classify_visibility(core.oriented, core.frame.d, ViewParams{}, flags);
  const auto lines = profile_plot(core.oriented, flags, core.frame, ViewParams{}, core.geotransform,
                                  12, lowest_height(core.oriented));
  QgsVectorLayer layer(run.results.value("OUTPUT").toString(), "p", "ogr");
  REQUIRE(layer.isValid());
  CHECK(layer.featureCount() == static_cast<long long>(lines.size()));
  CHECK(layer.fields().indexOf("section") >= 0);
  CHECK(layer.fields().indexOf("distance") >= 0);
  const Run bad = runAlgorithm(dem, {{"EVERY", 0}}, dir, nullptr, QStringLiteral("profileplot"));
  CHECK_FALSE(bad.ok);
}
