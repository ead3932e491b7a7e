// The panorama algorithm against the core.
#include <qgsrasterlayer.h>

#include "core/panorama/panorama.h"
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

namespace {

// The sample's highest cell's centre, as a point parameter in the DEM's CRS.
const QString kSummit = QStringLiteral("749008.1394,4009477.9308 [EPSG:32616]");

}  // namespace

TEST_CASE("the panorama algorithm draws the core's panorama on the map and in the panorama",
          "[plugin][panorama]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  // The thesis's filter, which the core runs by default; two samples a cell along each ray.
  const Run run = runOk(dem,
                        {{"OBSERVER", kSummit},
                         {"OBSERVER_HEIGHT", 2},
                         {"SAMPLES_PER_CELL", 2},
                         {"AZIMUTH_FROM", 270},
                         {"AZIMUTH_TO", 90},
                         {"FILTER", 1},
                         {"MAP_OUTPUT", dir.filePath("map.gpkg")},
                         {"PANORAMA_OUTPUT", dir.filePath("panorama.gpkg")},
                         {"VISIBILITY", dir.filePath("seen.tif")}},
                        dir, QStringLiteral("panorama"));
  const io::Dem core = coreDem(dem);
  PanoramaParams params;
  params.view.observer_x = 749008.1394, params.view.observer_y = 4009477.9308;
  params.view.observer_height = 2;
  params.view.azimuth_from = 270, params.view.azimuth_to = 90;
  params.view.samples_per_cell = 2;
  params.record_visibility = true;
  params.cut_leaps = true;  // as the algorithm draws its strokes
  const PanoramaResult expected = sketch_panorama(core.oriented, core.geotransform, params);
  REQUIRE(expected.strokes.size() > 100);
  QgsVectorLayer map(run.results.value("MAP_OUTPUT").toString(), "map", "ogr");
  QgsVectorLayer panorama(run.results.value("PANORAMA_OUTPUT").toString(), "panorama", "ogr");
  REQUIRE(map.isValid());
  REQUIRE(panorama.isValid());
  CHECK(map.featureCount() == static_cast<long long>(expected.strokes.size()));
  CHECK(panorama.featureCount() == static_cast<long long>(expected.strokes.size()));
  CHECK(map.crs().authid() == QStringLiteral("EPSG:32616"));
  // The panorama's x runs over the field of view, from 270 degrees a half turn on.
  const QgsRectangle extent = panorama.extent();
  CHECK(extent.xMinimum() >= 270.0);
  CHECK(extent.xMaximum() <= 450.0);
  // Every feature carries its azimuths, which bound its panorama line.
  QgsFeature feature;
  for (QgsFeatureIterator it = panorama.getFeatures(); it.nextFeature(feature);) {
    const QgsRectangle box = feature.geometry().boundingBox();
    CHECK(feature.attribute("azimuth_min").toDouble() == Approx(box.xMinimum()));
    CHECK(feature.attribute("azimuth_max").toDouble() == Approx(box.xMaximum()));
  }
  // The visibility raster is the core's.
  QgsRasterLayer seen(run.results.value("VISIBILITY").toString(), "seen", "gdal");
  REQUIRE(seen.isValid());
  const Grid<std::uint8_t> raster =
      visibility_raster(expected, core.rows, core.cols, core.geotransform);
  std::unique_ptr<QgsRasterBlock> block(
      seen.dataProvider()->block(1, seen.extent(), seen.width(), seen.height()));
  std::size_t same = 0;
  for (int r = 0; r < seen.height(); ++r)
    for (int c = 0; c < seen.width(); ++c)
      same += (block->isNoData(r, c) ? 255 : block->value(r, c)) == raster(r, c);
  CHECK(same == raster.size());
}

TEST_CASE("a raster output in another format than GeoTIFF is refused before the run",
          "[plugin][panorama][outputs]") {
  // The visibility raster in a GeoPackage failed in libpng ("Wrote palette index exceeding
  // num_palette"), and once its table reached the nodata value GDAL's PNG tiles renumbered it.
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runAlgorithm(dem,
                               {{"OBSERVER", kSummit},
                                {"MAP_OUTPUT", dir.filePath("map.gpkg")},
                                {"PANORAMA_OUTPUT", dir.filePath("panorama.gpkg")},
                                {"VISIBILITY", dir.filePath("seen.gpkg")}},
                               dir, nullptr, QStringLiteral("panorama"));
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("GeoTIFF"));
  CHECK(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
  const Run classes = runAlgorithm(dem, {{"OUTPUT", dir.filePath("classes.gpkg")}}, dir, nullptr,
                                   QStringLiteral("classification"));
  CHECK_FALSE(classes.ok);
  CHECK(classes.error.contains("GeoTIFF"));
}

TEST_CASE("the panorama algorithm refuses an observer off the DEM", "[plugin][panorama]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runAlgorithm(dem,
                               {{"OBSERVER", QStringLiteral("0,0 [EPSG:32616]")},
                                {"MAP_OUTPUT", dir.filePath("map.gpkg")},
                                {"PANORAMA_OUTPUT", dir.filePath("panorama.gpkg")}},
                               dir, nullptr, QStringLiteral("panorama"));
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains(QStringLiteral("outside the DEM")));
  CHECK_FALSE(QFileInfo::exists(dir.filePath("map.gpkg")));
}

TEST_CASE("the panorama algorithm labels the peaks the core sees", "[plugin][panorama]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const io::Dem core = coreDem(dem);
  // The DEM's cells over 900 m highest among their eight neighbours, as named points.
  std::vector<NamedPoint> peaks;
  QString json = QStringLiteral(R"({"type": "FeatureCollection", "crs": {"type": "name", )"
                                R"("properties": {"name": "EPSG:32616"}}, "features": [)");
  for (std::size_t r = 1; r + 1 < core.rows; ++r) {
    for (std::size_t c = 1; c + 1 < core.cols; ++c) {
      const float z = core.oriented(r, c);
      bool highest = z > 900;
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc)
          if (dr || dc) highest = highest && z > core.oriented(r + dr, c + dc);
      if (!highest) continue;
      double x, y;
      core.geotransform.apply({c + 0.5, r + 0.5}, x, y);
      const std::string name = "P" + std::to_string(peaks.size());
      peaks.push_back({name, x, y});
      json += QStringLiteral(R"(%1{"type": "Feature", "properties": {"label": "%2"}, )"
                             R"("geometry": {"type": "Point", "coordinates": [%3, %4]}})")
                  .arg(peaks.size() > 1 ? "," : "", QString::fromStdString(name))
                  .arg(x, 0, 'f', 4)
                  .arg(y, 0, 'f', 4);
    }
  }
  json += "]}";
  REQUIRE(peaks.size() > 5);
  QFile file(dir.filePath("peaks.geojson"));
  REQUIRE(file.open(QIODevice::WriteOnly));
  file.write(json.toUtf8());
  file.close();
  PanoramaView view;
  view.observer_x = 749008.1394, view.observer_y = 4009477.9308;
  view.observer_height = 2;
  const std::vector<SeenPeak> seen = see_peaks(
      core.oriented, core.geotransform, plan_rays(core.oriented, core.geotransform, view), peaks);
  REQUIRE(!seen.empty());
  REQUIRE(seen.size() < peaks.size());
  QStringList expected;
  for (const SeenPeak& s : seen) expected << QString::fromStdString(s.name);
  expected.sort();
  // As processing.run passes a path, and as the dialog, models and batch mode pass it: a
  // QgsProcessingOutputLayerDefinition, whose toString() is empty (the labels were never written).
  const QString labelsPath = dir.filePath("peaks.gpkg");
  for (const QVariant& peaksOutput :
       {QVariant(labelsPath),
        QVariant::fromValue(QgsProcessingOutputLayerDefinition(labelsPath))}) {
    CAPTURE(peaksOutput.typeName());
    QFile::remove(labelsPath);
    const Run run = runOk(dem,
                          {{"OBSERVER", kSummit},
                           {"OBSERVER_HEIGHT", 2},
                           {"PEAKS", dir.filePath("peaks.geojson")},
                           {"PEAK_NAMES", "label"},
                           {"MAP_OUTPUT", dir.filePath("map.gpkg")},
                           {"PANORAMA_OUTPUT", dir.filePath("panorama.gpkg")},
                           {"PEAKS_OUTPUT", peaksOutput}},
                          dir, QStringLiteral("panorama"));
    QgsVectorLayer labels(run.results.value("PEAKS_OUTPUT").toString(), "peaks", "ogr");
    REQUIRE(labels.isValid());
    CHECK(labels.featureCount() == static_cast<long long>(seen.size()));
    QStringList got;
    QgsFeature feature;
    for (QgsFeatureIterator it = labels.getFeatures(); it.nextFeature(feature);)
      got << feature.attribute("name").toString();
    got.sort();
    CHECK(got == expected);
  }
}
