// The drape algorithm against the core.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the drape algorithm equals the core's drape", "[plugin][drape]") {
  QTemporaryDir dir;
  const QString dem = kData + "/volcano.tif";
  // Drape the DEM onto itself: draped values are heights of visible cells.
  const Run run = runOk(dem, {{"SOURCE", dem}, {"AZIMUTH", 180}}, dir, QStringLiteral("drape"));
  const io::Dem core = coreDem(dem, 180);
  ViewParams view;
  view.azimuth_deg = 180;
  CellFlags flags;
  classify_visibility(core.oriented, core.frame.d, view, flags);
  const PlanObliqueDrape drape(core.oriented, flags, core.frame, view,
                               lowest_height(core.oriented));
  const HeightGrid expected = drape.drape(io::read_bands(dem.toStdString()).at(0));
  QgsRasterLayer layer(run.results.value("OUTPUT").toString(), "d", "gdal");
  REQUIRE(layer.isValid());
  REQUIRE(static_cast<std::size_t>(layer.width()) == drape.cols());
  REQUIRE(static_cast<std::size_t>(layer.height()) == drape.rows());
  std::unique_ptr<QgsRasterBlock> block(
      layer.dataProvider()->block(1, layer.extent(), layer.width(), layer.height()));
  for (int r = 0; r < layer.height(); ++r)
    for (int c = 0; c < layer.width(); ++c) {
      const float e = expected(static_cast<std::size_t>(r), static_cast<std::size_t>(c));
      bool noData = false;
      const double v = block->valueAndNoData(r, c, noData);
      if (is_data(e)) {
        REQUIRE(v == Approx(e));
      } else {
        REQUIRE((noData || std::isnan(v)));
      }
    }
  const Run mismatch = runAlgorithm(dem, {{"SOURCE", kData + "/bei_5m_local.tif"}}, dir, nullptr,
                                    QStringLiteral("drape"));
  CHECK_FALSE(mismatch.ok);
  CHECK(mismatch.error.contains("resample it to the DEM's grid"));
}

TEST_CASE("the drape hears Cancel while it lays out, and its progress moves", "[plugin][drape]") {
  // Laying out the drape (30 to 60 %) used to run to its end without a word: a Cancel there was
  // heard only after the first band was draped.
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  CancelAt feedback(31);
  const Run run = runAlgorithm(dem, {{"SOURCE", dem}}, dir, &feedback, QStringLiteral("drape"));
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains(QStringLiteral("Cancel")));
  CHECK_FALSE(QFileInfo::exists(dir.filePath("out.tif")));
}
