// The Silhouettes algorithm run headless on real DEMs: features, fields, CRS and figures equal
// the core's, strip by strip through the provider too.
#include "plugin/run_notes.h"
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("the algorithm's strokes equal the core's on real DEMs", "[plugin]") {
  struct Case {
    const char* file;
    double azimuth;
    int geometry;
    int epsg;
  };
  for (const Case& c :
       {Case{"jacksboro_utm16n.tif", 90, 0, 32616}, Case{"gorillas_utm32n.tif", 270, 1, 32632},
        Case{"volcano.tif", 180, 0, 0}, Case{"jacksboro_utm16n.tif", 135, 1, 32616}}) {
    CAPTURE(c.file, c.azimuth);
    QTemporaryDir dir;
    const Run run =
        runAlgorithm(kData + "/" + c.file, {{"AZIMUTH", c.azimuth}, {"GEOMETRY", c.geometry}}, dir);
    INFO(run.error.toStdString());
    REQUIRE(run.ok);
    const SilhouetteResult core =
        coreResult(kData + "/" + c.file, c.azimuth, c.geometry ? Geometry::oblique : Geometry::map);
    CHECK(run.results.value("FACTUAL_STROKES").toDouble() == core.stats.factual_strokes);
    CHECK(run.results.value("FSET_PCT").toDouble() == Approx(core.stats.pct(core.stats.filtered)));

    QgsVectorLayer factual(run.results.value("FACTUAL").toString(), "f", "ogr");
    QgsVectorLayer formulated(run.results.value("FORMULATED").toString(), "o", "ogr");
    REQUIRE(factual.isValid());
    REQUIRE(formulated.isValid());
    CHECK(factual.featureCount() == static_cast<long long>(core.stats.factual_strokes));
    CHECK(formulated.featureCount() == static_cast<long long>(core.stats.formulated_strokes));
    if (c.epsg) {
      CHECK(factual.crs().authid() == QStringLiteral("EPSG:%1").arg(c.epsg));
    } else {
      // QGIS gives a layer without CRS a default one on loading: ask GDAL what the file holds.
      // GeoPackage records "no CRS" as its undefined SRS (srs_id 0).
      GDALDatasetH ds = GDALOpenEx(run.results.value("FACTUAL").toString().toUtf8().constData(),
                                   GDAL_OF_VECTOR, nullptr, nullptr, nullptr);
      REQUIRE(ds != nullptr);
      OGRSpatialReferenceH srs = OGR_L_GetSpatialRef(GDALDatasetGetLayer(ds, 0));
      CHECK((srs == nullptr || std::string(OSRGetName(srs)).find("Undefined") == 0));
      GDALClose(ds);
    }
    for (const char* field : {"class", "cells", "length", "mean_slope", "mean_row_slope",
                              "mean_depth", "max_depth", "mean_dist", "mean_z"}) {
      CHECK(factual.fields().indexOf(field) >= 0);
    }
    // Same strokes in the same order: compare every vertex of the factual ones.
    QgsFeatureIterator it = factual.getFeatures();
    QgsFeature feature;
    std::size_t k = 0;
    while (it.nextFeature(feature)) {
      const Stroke& s = core.strokes[k++];
      REQUIRE(feature.attribute("class").toString() == "factual");
      REQUIRE(feature.attribute("cells").toInt() == s.cells);
      const QgsGeometry g = feature.geometry();
      const QgsPolylineXY line = g.asPolyline();
      REQUIRE(static_cast<std::size_t>(line.size()) == s.points.size());
      for (int q = 0; q < line.size(); ++q) {
        REQUIRE(line[q].x() == Approx(s.points[static_cast<std::size_t>(q)].x));
        REQUIRE(line[q].y() == Approx(s.points[static_cast<std::size_t>(q)].y));
      }
    }
    // QGIS wrote them without an index; the algorithm then built it in bulk, on pages sized for it.
    const std::string factualFile =
        run.results.value("FACTUAL").toString().section('|', 0, 0).toStdString();
    test::check_spatial_index(factualFile, "factual");
    CHECK(test::IndexedGpkg(factualFile, "factual").page_size() == 16384);
    test::check_spatial_index(
        run.results.value("FORMULATED").toString().section('|', 0, 0).toStdString(), "formulated");
    QgsFeatureIterator fo = formulated.getFeatures();
    while (fo.nextFeature(feature)) {
      REQUIRE(feature.attribute("class").toString() == "formulated");
      REQUIRE(feature.attribute("mean_depth").isNull());
    }
  }
}

TEST_CASE("strips through the raster provider give the whole-DEM strokes", "[plugin][strips]") {
  const QString dem = kData + "/gorillas_utm32n.tif";
  // The cardinal views read windows of rows or columns; the others the band each strip samples.
  for (double az : {0.0, 90.0, 180.0, 270.0, 45.0, 200.0}) {
    CAPTURE(az);
    QTemporaryDir dir;
    const Run run = runAlgorithm(dem, {{"AZIMUTH", az}, {"GEOMETRY", 1}, {"STRIPS", 17}}, dir);
    INFO(run.error.toStdString());
    REQUIRE(run.ok);
    const SilhouetteResult core = coreResult(dem, az, Geometry::oblique);
    CHECK(run.results.value("GSET_PCT").toDouble() ==
          Approx(core.stats.pct(core.stats.generalised)));
    for (const char* output : {"FACTUAL", "FORMULATED"}) {
      QgsVectorLayer layer(run.results.value(output).toString(), "l", "ogr");
      REQUIRE(layer.isValid());
      const StrokeClass cls =
          std::string(output) == "FACTUAL" ? StrokeClass::factual : StrokeClass::formulated;
      std::vector<const Stroke*> expected;
      for (const Stroke& s : core.strokes)
        if (s.cls == cls) expected.push_back(&s);
      REQUIRE(layer.featureCount() == static_cast<long long>(expected.size()));
      QgsFeatureIterator it = layer.getFeatures();
      QgsFeature feature;
      std::size_t k = 0;
      while (it.nextFeature(feature)) {
        const QgsPolylineXY line = feature.geometry().asPolyline();
        REQUIRE(static_cast<std::size_t>(line.size()) == expected[k]->points.size());
        REQUIRE(line.front().x() == Approx(expected[k]->points.front().x));
        REQUIRE(line.back().y() == Approx(expected[k]->points.back().y));
        ++k;
      }
    }
  }
}

TEST_CASE("both outputs can go into one new GeoPackage", "[plugin][outputs]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const QString file = dir.filePath("both.gpkg");
  const auto layer = [&file](const char* name) {
    return QStringLiteral("ogr:dbname='%1' table=\"%2\" (geom)").arg(file, name);
  };
  const Run run =
      runAlgorithm(dem, {{"FACTUAL", layer("factual")}, {"FORMULATED", layer("formulated")}}, dir);
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  CHECK(layerNames(file) == (QStringList{"factual", "formulated"}));
  const SilhouetteResult core = coreResult(dem, 90, Geometry::map);
  QgsVectorLayer factual(run.results.value("FACTUAL").toString(), "f", "ogr");
  QgsVectorLayer formulated(run.results.value("FORMULATED").toString(), "o", "ogr");
  CHECK(factual.featureCount() == static_cast<long long>(core.stats.factual_strokes));
  CHECK(formulated.featureCount() == static_cast<long long>(core.stats.formulated_strokes));
}

TEST_CASE("the strips are mentioned only when the DEM takes more than one", "[plugin][strips]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";  // 436 x 414: one strip
  RecordingFeedback whole, strips;
  REQUIRE(runAlgorithm(dem, {}, dir, &whole).ok);
  CHECK_FALSE(whole.infos.join(' ').contains(QStringLiteral("strips")));
  REQUIRE(runAlgorithm(dem, {{"STRIPS", 100}}, dir, &strips).ok);
  CHECK(strips.infos.join(' ').contains(QStringLiteral("in 5 strips of 100 profiles")));
  // Drawn for 1:1 000 000, the run sketches the DEM averaged 5 x 5 cells: 88 x 83 cells.
  RecordingFeedback averaged;
  REQUIRE(runAlgorithm(dem, {{"STRIPS", 20}, {"DRAWN_FOR", 1000000}}, dir, &averaged).ok);
  CHECK(averaged.infos.join(' ').contains(QStringLiteral("in 5 strips of 20 profiles")));
}

TEST_CASE("drawn for a small scale, the sketch keeps its big landforms only", "[plugin][scale]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run own = runAlgorithm(dem, {{"AZIMUTH", 250}}, dir);
  REQUIRE(own.ok);
  QTemporaryDir small;
  RecordingFeedback told;
  const Run scaled = runAlgorithm(dem, {{"AZIMUTH", 250}, {"DRAWN_FOR", 1000000}}, small, &told);
  INFO(scaled.error.toStdString());
  REQUIRE(scaled.ok);
  // The same run as the command line's --drawn-for: the DEM averaged to 375 m cells (0.4 mm on
  // paper), and fewer strokes, each at least 2 mm on paper: 2 km, 6 cells of 375 m.
  const double ownStrokes = own.results.value("FACTUAL_STROKES").toDouble();
  const double scaledStrokes = scaled.results.value("FACTUAL_STROKES").toDouble();
  CHECK(scaledStrokes > 0);
  CHECK(scaledStrokes < ownStrokes / 4);
  QgsVectorLayer factual(scaled.results.value("FACTUAL").toString(), "f", "ogr");
  REQUIRE(factual.isValid());
  QgsFeature feature;
  for (QgsFeatureIterator it = factual.getFeatures(); it.nextFeature(feature);)
    CHECK(feature.attribute(QStringLiteral("cells")).toInt() >= 6);
  CHECK(told.infos.join(' ').contains(QStringLiteral("the DEM was averaged 5 x 5 cells first")));
}

TEST_CASE("the run notes keep a layer's name as it is, placeholders and all", "[plugin][notes]") {
  ViewParams view;
  view.azimuth_deg = 250;
  FilterReport filter;
  DrawnParams strokes;
  strokes.mode = StrokeMode::drawn;
  strokes.scale = 250000;
  const QString dem = QStringLiteral("odd %1 %2 name, band 1");
  const QString sketch = plugin::sketchNote(dem, view, filter, strokes);
  CHECK(sketch.startsWith(dem + QStringLiteral(". Seen from 250° (azimuth), vertical "
                                               "exaggeration 2.5, base slope 40 %; the thesis's")));
  CHECK(sketch.contains(QStringLiteral("; drawn strokes for 1:250,000. Terrain Sketch ")));
  const plugin::RunNote product = plugin::productNote(dem, QStringLiteral("Row slope"), view);
  CHECK(product.title == QStringLiteral("Row slope, from 250°"));
  CHECK(product.abstract.startsWith(dem + QStringLiteral(". Row slope seen from 250°")));
}

TEST_CASE("a run that draws no stroke warns which stage left nothing", "[plugin][robustness]") {
  QTemporaryDir dir;
  // A flat DEM in UTM: nothing hidden, no slope seen edge-on.
  const QString flat = dir.filePath(QStringLiteral("flat.tif"));
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), flat.toUtf8().constData(), 40, 40, 1,
                               GDT_Float32, nullptr);
  REQUIRE(ds != nullptr);
  double geotransform[6] = {500000, 10, 0, 4000000, 0, -10};
  GDALSetGeoTransform(ds, geotransform);
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  OSRImportFromEPSG(srs, 32616);
  GDALSetSpatialRef(ds, srs);
  OSRDestroySpatialReference(srs);
  REQUIRE(GDALFillRaster(GDALGetRasterBand(ds, 1), 100.0, 0.0) == CE_None);
  GDALClose(ds);
  RecordingFeedback flatRun;
  const Run run = runAlgorithm(flat, {}, dir, &flatRun);
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  CHECK(run.results.value("FACTUAL_STROKES").toDouble() == 0);
  CHECK(run.results.value("FORMULATED_STROKES").toDouble() == 0);
  CHECK(flatRun.warnings.join(' ').contains(
      QStringLiteral("No strokes: no cell of the DEM is hidden")));
  // The same raster with its one height declared nodata: no cell at all, said so, and no fill
  // value made up from QGIS's statistics of no cell (+-DBL_MAX).
  ds = GDALOpen(flat.toUtf8().constData(), GA_Update);
  REQUIRE(ds != nullptr);
  GDALSetRasterNoDataValue(GDALGetRasterBand(ds, 1), 100.0);
  GDALClose(ds);
  RecordingFeedback nodataRun;
  REQUIRE(runAlgorithm(flat, {}, dir, &nodataRun).ok);
  const QString nodataWarnings = nodataRun.warnings.join(' ');
  CHECK(nodataWarnings.contains(QStringLiteral("No strokes: every cell of the DEM is nodata")));
  CHECK_FALSE(nodataWarnings.contains(QStringLiteral("fill value")));
  CHECK_FALSE(nodataWarnings.contains(QStringLiteral("no cell of the DEM is hidden")));
  // A real DEM whose chains are all shorter than the shortest stroke asked for.
  const QString sample = kData + "/jacksboro_utm16n.tif";
  RecordingFeedback shortRun;
  REQUIRE(runAlgorithm(sample, {{"STROKES", 1}, {"MIN_CELLS", 5000}}, dir, &shortRun).ok);
  CHECK(shortRun.warnings.join(' ').contains(
      QStringLiteral("every chain was shorter than the shortest stroke kept")));
  // The defaults draw strokes, and warn of none.
  RecordingFeedback defaults;
  REQUIRE(runAlgorithm(sample, {}, dir, &defaults).ok);
  CHECK_FALSE(defaults.warnings.join(' ').contains(QStringLiteral("No strokes")));
}
