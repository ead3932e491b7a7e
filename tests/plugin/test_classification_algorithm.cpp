// The classification algorithm against the core.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the classification raster holds the core's stage counts", "[plugin][diagnostics]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runOk(dem, {}, dir, QStringLiteral("classification"));
  const SilhouetteResult core = coreResult(dem, 90, Geometry::map);
  QgsRasterLayer layer(run.results.value("OUTPUT").toString(), "c", "gdal");
  REQUIRE(layer.isValid());
  CHECK(layer.crs().authid() == "EPSG:32616");
  std::unique_ptr<QgsRasterBlock> block(
      layer.dataProvider()->block(1, layer.extent(), layer.width(), layer.height()));
  std::size_t thinned = 0, occluding = 0;
  for (int r = 0; r < layer.height(); ++r)
    for (int c = 0; c < layer.width(); ++c) {
      const double v = block->value(r, c);
      thinned += v == 6, occluding += v == 3;
    }
  CHECK(thinned == core.stats.thinned);
  CHECK(run.results.value("TSET_PCT").toDouble() == Approx(core.stats.pct(core.stats.thinned)));
  CHECK(occluding > 0);
}
