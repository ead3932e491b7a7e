// The drape algorithm against the core.
#include <gdal_utils.h>

#include <limits>

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

TEST_CASE("a raster to drape on other ground or in another CRS is refused", "[plugin][drape]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  // The same cells, shifted by a kilometre, and the same grid said to be in the next UTM zone.
  const QString shifted = dir.filePath("shifted.tif"), zone17 = dir.filePath("zone17.tif");
  for (const auto& [path, option] :
       {std::pair{shifted, QStringList{"-a_ullr", "732795.639415354", "4038415.4307843",
                                       "763845.639415354", "4005715.4307843"}},
        std::pair{zone17, QStringList{"-a_srs", "EPSG:32617"}}}) {
    QStringList args = option;
    std::vector<QByteArray> bytes;
    for (const QString& a : args) bytes.push_back(a.toUtf8());
    std::vector<char*> argv;
    for (QByteArray& b : bytes) argv.push_back(b.data());
    argv.push_back(nullptr);
    GDALTranslateOptions* options = GDALTranslateOptionsNew(argv.data(), nullptr);
    GDALDatasetH in = GDALOpen(dem.toUtf8().constData(), GA_ReadOnly);
    REQUIRE(in != nullptr);
    GDALDatasetH out = GDALTranslate(path.toUtf8().constData(), in, options, nullptr);
    GDALTranslateOptionsFree(options);
    REQUIRE(out != nullptr);
    GDALClose(out);
    GDALClose(in);
  }
  const Run offGround =
      runAlgorithm(dem, {{"SOURCE", shifted}}, dir, nullptr, QStringLiteral("drape"));
  CHECK_FALSE(offGround.ok);
  CHECK(offGround.error.contains("warp it onto the DEM's grid"));
  const Run otherCrs =
      runAlgorithm(dem, {{"SOURCE", zone17}}, dir, nullptr, QStringLiteral("drape"));
  CHECK_FALSE(otherCrs.ok);
  CHECK(otherCrs.error.contains("EPSG:32617"));
  CHECK_FALSE(QFileInfo::exists(dir.filePath("out.tif")));
}

// (No semicolon in a test's name: CMake's lists cut it there, and the test ran under a name that
// matched none, passing without a check.)
TEST_CASE(
    "a drape with nothing in sight is one empty cell, and one of heights beyond terrain is "
    "refused",
    "[plugin][drape]") {
  QTemporaryDir dir;
  const QString empty = dir.filePath("allnan.tif"), spike = dir.filePath("spike.tif");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  test::write_tiff(
      empty.toStdString(), 30, 30, 1, [=](int, int, int) { return nan; }, test::kNorthUp, 32616);
  test::write_tiff(
      spike.toStdString(), 20, 20, 1, [](int, int r, int c) { return r + c == 0 ? 0.f : 1e25f; },
      test::kNorthUp, 32616);
  const Run run = runAlgorithm(empty, {{"SOURCE", empty}, {"AZIMUTH", 33}}, dir, nullptr, "drape");
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  QgsRasterLayer layer(run.results.value("OUTPUT").toString(), "d", "gdal");
  REQUIRE(layer.isValid());
  CHECK(layer.width() == 1);
  const Run refused =
      runAlgorithm(spike, {{"SOURCE", spike}, {"AZIMUTH", 33}}, dir, nullptr, "drape");
  CHECK_FALSE(refused.ok);
  CHECK(refused.error.contains("far larger than the DEM's 20 x 20 cells"));
}
