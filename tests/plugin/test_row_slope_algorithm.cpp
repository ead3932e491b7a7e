// The row slope algorithm against the core.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the row slope map equals the core's", "[plugin][diagnostics]") {
  const QString dem = kData + "/volcano.tif";
  const io::Dem core = coreDem(dem, 30);
  QTemporaryDir dir;
  const Run run = runOk(dem, {{"AZIMUTH", 30}}, dir, QStringLiteral("rowslope"));
  const HeightGrid expected = row_slope_map(core.oriented, core.frame);
  QgsRasterLayer layer(run.results.value("OUTPUT").toString(), "r", "gdal");
  REQUIRE(layer.isValid());
  std::unique_ptr<QgsRasterBlock> block(
      layer.dataProvider()->block(1, layer.extent(), layer.width(), layer.height()));
  int compared = 0;
  for (int r = 0; r < layer.height(); ++r)
    for (int c = 0; c < layer.width(); ++c) {
      const float e = expected(static_cast<std::size_t>(r), static_cast<std::size_t>(c));
      bool noData = false;
      const double v = block->valueAndNoData(r, c, noData);
      if (!is_data(e)) {
        REQUIRE((noData || std::isnan(v)));
      } else {
        REQUIRE(v == Approx(e).margin(1e-4));
        ++compared;
      }
    }
  CHECK(compared > 3000);
}
