// Outputs whole or not at all: cancels, full disks, clashing outputs, layers added to existing
// files, streaming into every format.
#include <gdal_utils.h>

#include "plugin_test_support.h"

using namespace tsk::plugin_test;

TEST_CASE("cancelling stops the run with an error and no result", "[plugin]") {
  CancelAt feedback(0);
  QTemporaryDir dir;
  const Run run = runAlgorithm(kData + "/jacksboro_utm16n.tif", {}, dir, &feedback);
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("Cancelled"));
  CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
}

TEST_CASE("an output that cannot be written fails the run and leaves no other output",
          "[plugin][outputs]") {
  QTemporaryDir dir;
  for (const char* format : {"gpkg", "shp"}) {
    CAPTURE(format);
    const QString missing = dir.filePath(QStringLiteral("missing/formulated.%1").arg(format));
    const Run run =
        runAlgorithm(kData + "/jacksboro_utm16n.tif",
                     {{"FACTUAL", dir.filePath(QStringLiteral("factual.%1").arg(format))},
                      {"FORMULATED", missing}},
                     dir);
    CHECK_FALSE(run.ok);
    INFO(run.error.toStdString());
    CHECK(run.error.contains(missing));
    CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
  }
}

TEST_CASE("a disk that fills up fails the run in every format and leaves no file",
          "[plugin][outputs]") {
  // A file size limit on this process stands in for a full disk (writes past it fail, EFBIG).
  // The GeoJSON, KML, GML and CSV drivers ignore failed writes: QGIS reported such cut-off
  // files as written.
  QTemporaryDir dir;
  for (const char* format : {"geojson", "kml", "gml", "csv", "gpkg", "shp", "fgb"}) {
    CAPTURE(format);
    const Run run = [&] {
      const FileSizeLimit full(64 * 1024);
      return runAlgorithm(kData + "/jacksboro_utm16n.tif", outputsAs(dir, format), dir);
    }();
    INFO(run.error.toStdString());
    CHECK_FALSE(run.ok);
    const QStringList left = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
    INFO(left.join(' ').toStdString());
    CHECK(left.isEmpty());
    for (const QString& file : left) QFile::remove(dir.filePath(file));
  }
  // Without the limit each of them is written whole.
  for (const char* format : {"geojson", "kml", "gml", "csv"}) {
    CAPTURE(format);
    const Run run = runAlgorithm(kData + "/jacksboro_utm16n.tif", outputsAs(dir, format), dir);
    INFO(run.error.toStdString());
    CHECK(run.ok);
  }
}

TEST_CASE("a disk that fills up fails a raster or page output and leaves no file",
          "[plugin][outputs]") {
  // As above. GDAL writes a GeoTIFF's cached blocks as it closes it, where QGIS only logs the
  // failure: the runs succeeded with the first 64 kB of their raster.
  QTemporaryDir dir;
  for (const char* id : {"classification", "rowslope", "filterdiagram"}) {
    CAPTURE(id);
    const QVariantMap output = id == std::string("filterdiagram")
                                   ? QVariantMap{{"OUTPUT", dir.filePath("out.html")}}
                                   : QVariantMap();
    const Run run = [&] {
      const FileSizeLimit full(16 * 1024);
      return runAlgorithm(kData + "/jacksboro_utm16n.tif", output, dir, nullptr, id);
    }();
    INFO(run.error.toStdString());
    CHECK_FALSE(run.ok);
    // GDAL 3.6 raises libtiff's "File too large". GDAL 3.10 leaves it to libtiff, which prints
    // it, and says only that a write failed or that the file does not read back.
    const bool gdal310 = GDAL_VERSION_NUM >= GDAL_COMPUTE_VERSION(3, 10, 0);
    CHECK((run.error.contains("File too large") ||
           (gdal310 &&
            (run.error.contains("Write error") || run.error.contains("does not read back")))));
    CHECK(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    CHECK(runAlgorithm(kData + "/jacksboro_utm16n.tif", output, dir, nullptr, id).ok);
    // The classes' names go in GDAL's side file.
    for (const char* name : {"out.tif", "out.tif.aux.xml", "out.html"})
      QFile::remove(dir.filePath(name));
  }
}

// The size of `file` staged by a run in `dir` (io/write/output_set.h), or 0 while there is none.
qint64 stagedSize(const QTemporaryDir& dir, const QString& file) {
  for (const QString& folder :
       QDir(dir.path()).entryList({"." + file + ".partial-*"}, QDir::Dirs | QDir::Hidden))
    return QFileInfo(QDir(dir.filePath(folder)).filePath(file)).size();
  return 0;
}

TEST_CASE("a cancelled run removes the strokes it wrote and keeps the earlier output whole",
          "[plugin][outputs]") {
  QTemporaryDir dir;
  const QString dem = kData + "/gorillas_utm32n.tif", shapefile = dir.filePath("factual.shp");
  // An earlier run's output, the one a failed run of the same name must leave.
  REQUIRE(runAlgorithm(dem, {{"AZIMUTH", 0}, {"FACTUAL", shapefile}}, dir).ok);
  const QStringList before = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
  const long long featuresBefore = QgsVectorLayer(shapefile, "before", "ogr").featureCount();
  REQUIRE(featuresBefore > 0);
  // Exact strokes go to the outputs as they complete: halfway, the staged shapefile holds some.
  // (Drawn strokes wait until no later chain can join them, and are written from another thread:
  // how many are in the file at a given moment is not fixed.)
  qint64 stagedBytes = 0;
  CancelAt feedback(50, [&] { stagedBytes = stagedSize(dir, "factual.shp"); });
  const Run run =
      runAlgorithm(dem, {{"STRIPS", 17}, {"STROKES", 1}, {"FACTUAL", shapefile}}, dir, &feedback);
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("Cancelled"));
  CHECK(stagedBytes > 1000);
  CHECK(
      QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::Dirs | QDir::NoDotAndDotDot) ==
      before);
  CHECK(QgsVectorLayer(shapefile, "after", "ogr").featureCount() == featuresBefore);
}

TEST_CASE("a cancelled run drops the layer it added to an existing GeoPackage",
          "[plugin][outputs]") {
  QTemporaryDir dir;
  const QString dem = kData + "/gorillas_utm32n.tif";
  const QString base = dir.filePath("base.gpkg");
  REQUIRE(runAlgorithm(dem, {{"FACTUAL", base}}, dir).ok);
  const QStringList before = layerNames(base);
  REQUIRE(before.size() == 1);
  const QString added = QStringLiteral("ogr:dbname='%1' table=\"added\" (geom)").arg(base);

  CancelAt feedback(50);
  const Run cancelled = runAlgorithm(dem, {{"STRIPS", 17}, {"FACTUAL", added}}, dir, &feedback);
  CHECK_FALSE(cancelled.ok);
  CHECK(layerNames(base) == before);
  QgsVectorLayer kept(base, "kept", "ogr");
  CHECK(kept.featureCount() > 0);

  const Run run = runAlgorithm(dem, {{"FACTUAL", added}}, dir);
  REQUIRE(run.ok);
  CHECK(layerNames(base) == (before + QStringList{"added"}));
  QgsVectorLayer layer(run.results.value("FACTUAL").toString(), "added", "ogr");
  CHECK(layer.featureCount() == kept.featureCount());
}

TEST_CASE("an output into the file of a raster being read is refused, the raster kept",
          "[plugin][outputs][robustness]") {
  QTemporaryDir dir;
  // A DEM in a GeoPackage, where the strokes could go too, and one in a GeoTIFF.
  const QString gpkg = dir.filePath("dem.gpkg");
  const QString tiff = dir.filePath("dem.tif");
  REQUIRE(QFile::copy(kData + "/jacksboro_utm16n.tif", tiff));
  REQUIRE(QFile::copy(kData + "/jacksboro_utm16n.tif.aux.xml", tiff + ".aux.xml"));
  test::copy_raster_to_gpkg(QFile::encodeName(tiff).toStdString(),
                            QFile::encodeName(gpkg).toStdString());
  const auto bytes = [](const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
  };
  const QByteArray gpkgBytes = bytes(gpkg), tiffBytes = bytes(tiff);
  REQUIRE(!gpkgBytes.isEmpty());
  struct Case {
    QString id, input;
    QVariantMap extra;
  };
  const QString addedLayer = QStringLiteral("ogr:dbname='%1' table=\"added\" (geom)").arg(gpkg);
  // A VRT reading the GeoTIFF: the GeoTIFF is read too.
  const QString vrt = dir.filePath("v_dem.vrt");
  {
    const QByteArray source = QFile::encodeName(tiff);
    const char* sources[] = {source.constData()};
    GDALDatasetH built =
        GDALBuildVRT(QFile::encodeName(vrt).constData(), 1, nullptr, sources, nullptr, nullptr);
    REQUIRE(built != nullptr);
    GDALClose(built);
  }
  const Case cases[] = {
      {"silhouettes", gpkg, {{"FACTUAL", gpkg}}},
      {"classification", vrt, {{"OUTPUT", tiff}}},
      {"rowslope", vrt, {{"OUTPUT", tiff}}},
      {"silhouettes", gpkg, {{"FORMULATED", addedLayer}}},
      {"profileplot", gpkg, {{"OUTPUT", dir.filePath("./dem.gpkg")}}},
      {"classification", tiff, {{"OUTPUT", tiff}}},
      {"drape", gpkg, {{"SOURCE", tiff}, {"OUTPUT", tiff}}},
  };
  for (const Case& c : cases) {
    CAPTURE(c.id.toStdString(), c.extra.keys().join(' ').toStdString());
    const Run run = runAlgorithm(c.input, c.extra, dir, nullptr, c.id);
    CHECK_FALSE(run.ok);
    CHECK(run.error.contains("which this algorithm reads"));
    CHECK(bytes(gpkg) == gpkgBytes);
    CHECK(bytes(tiff) == tiffBytes);
    CHECK(QDir(dir.path()).entryList(QDir::Files).join(' ').toStdString() ==
          "dem.gpkg dem.tif dem.tif.aux.xml v_dem.vrt");
  }
  // Beside the raster, in a file of their own, the outputs are written.
  const Run run = runAlgorithm(gpkg, {}, dir);
  INFO(run.error.toStdString());
  CHECK(run.ok);
}

TEST_CASE("an output into a file the algorithm reads is refused before the run",
          "[plugin][outputs][robustness]") {
  QTemporaryDir dir;
  const QString dem = dir.filePath("dem.tif");
  REQUIRE(QFile::copy(kData + "/volcano.tif", dem));
  const QByteArray before = [&] {
    QFile file(dem);
    REQUIRE(file.open(QIODevice::ReadOnly));
    return file.readAll();
  }();
  const Run run = runAlgorithm(dem, {{"OUTPUT", dir.filePath("./dem.tif")}}, dir, nullptr,
                               QStringLiteral("classification"));
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("which this algorithm reads"));
  QFile file(dem);
  REQUIRE(file.open(QIODevice::ReadOnly));
  CHECK(file.readAll() == before);
}

TEST_CASE("an output into a file a nested VRT reads is refused", "[plugin][outputs][robustness]") {
  QTemporaryDir dir;
  const QString src = dir.filePath("src.tif");
  REQUIRE(QFile::copy(kData + "/volcano.tif", src));
  // v.vrt reads src.tif; vv.vrt reads v.vrt, and GDAL lists only v.vrt for it.
  for (const auto& [vrt, source] : {std::pair{QStringLiteral("v.vrt"), src},
                                    std::pair{QStringLiteral("vv.vrt"), dir.filePath("v.vrt")}}) {
    GDALDatasetH in = GDALOpen(source.toUtf8().constData(), GA_ReadOnly);
    REQUIRE(in != nullptr);
    GDALDatasetH out =
        GDALBuildVRT(dir.filePath(vrt).toUtf8().constData(), 1, &in, nullptr, nullptr, nullptr);
    REQUIRE(out != nullptr);
    GDALClose(out);
    GDALClose(in);
  }
  QFile file(src);
  REQUIRE(file.open(QIODevice::ReadOnly));
  const QByteArray before = file.readAll();
  file.close();
  const Run classification = runAlgorithm(dir.filePath("vv.vrt"), {{"OUTPUT", src}}, dir, nullptr,
                                          QStringLiteral("classification"));
  CHECK_FALSE(classification.ok);
  CHECK(classification.error.contains("which this algorithm reads"));
  const Run drape =
      runAlgorithm(kData + "/volcano.tif", {{"SOURCE", dir.filePath("vv.vrt")}, {"OUTPUT", src}},
                   dir, nullptr, QStringLiteral("drape"));
  CHECK_FALSE(drape.ok);
  CHECK(drape.error.contains("which this algorithm reads"));
  REQUIRE(file.open(QIODevice::ReadOnly));
  CHECK(file.readAll() == before);
}

TEST_CASE("two outputs into one file are refused unless both add a layer",
          "[plugin][outputs][robustness]") {
  QTemporaryDir dir;
  const QString dem = kData + "/volcano.tif";
  const auto layer = [&dir](const char* name) {
    return QStringLiteral("ogr:dbname='%1' table=\"%2\" (geom)")
        .arg(dir.filePath("both.gpkg"), name);
  };
  // The second output made would write over the first: the factual strokes were lost.
  const QVariantMap clashes[] = {
      {{"FACTUAL", dir.filePath("both.shp")}, {"FORMULATED", dir.filePath("./both.shp")}},
      {{"FACTUAL", dir.filePath("both.gpkg")}, {"FORMULATED", dir.filePath("both.gpkg")}},
      {{"FACTUAL", dir.filePath("both.gpkg")}, {"FORMULATED", layer("formulated")}},
  };
  std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm());
  for (const QVariantMap& outputs : clashes) {
    CAPTURE(outputs.value("FORMULATED").toString().toStdString());
    const Run run = runAlgorithm(dem, outputs, dir);
    CHECK_FALSE(run.ok);
    CHECK(run.error.contains("would both be written"));
    CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
    // The dialog and batch mode ask before they run.
    QVariantMap parameters = outputs;
    parameters.insert("INPUT", dem);
    parameters.insert("BAND", 1);
    QgsProcessingContext context;
    QString message;
    CHECK_FALSE(alg->checkParameterValues(parameters, context, &message));
    CHECK(message.contains("would both be written"));
  }
  // So are parameters that are each in range but not together.
  QgsProcessingContext context;
  QString message;
  const QVariantMap good{{"INPUT", dem},
                         {"BAND", 1},
                         {"FACTUAL", "TEMPORARY_OUTPUT"},
                         {"FORMULATED", "TEMPORARY_OUTPUT"}};
  CHECK(alg->checkParameterValues(good, context, &message));
  QVariantMap crossed = good;
  crossed.insert("CTRL_COL", 13);
  CHECK_FALSE(alg->checkParameterValues(crossed, context, &message));
  CHECK(message.contains("control point"));
  const Run run =
      runAlgorithm(dem, {{"FACTUAL", layer("factual")}, {"FORMULATED", layer("formulated")}}, dir);
  INFO(run.error.toStdString());
  CHECK(run.ok);
}

TEST_CASE("strokes stream into shapefiles and memory layers too", "[plugin][outputs]") {
  const QString dem = kData + "/jacksboro_utm16n.tif";
  QTemporaryDir dir;
  QgsProcessingContext context;
  const Run run = runAlgorithm(
      dem, {{"FACTUAL", dir.filePath("factual.shp")}, {"FORMULATED", "TEMPORARY_OUTPUT"}}, dir,
      nullptr, QStringLiteral("silhouettes"), &context);
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  const SilhouetteResult core = coreResult(dem, 90, Geometry::map);
  QgsVectorLayer shapefile(run.results.value("FACTUAL").toString(), "f", "ogr");
  auto* memory = qobject_cast<QgsVectorLayer*>(
      QgsProcessingUtils::mapLayerFromString(run.results.value("FORMULATED").toString(), context));
  REQUIRE(shapefile.isValid());
  REQUIRE(memory != nullptr);
  CHECK(memory->providerType() == "memory");
  std::size_t k = 0;
  for (QgsVectorLayer* layer : {&shapefile, memory}) {
    QgsFeatureIterator it = layer->getFeatures();
    QgsFeature feature;
    while (it.nextFeature(feature)) {
      REQUIRE(k < core.strokes.size());
      const Stroke& s = core.strokes[k++];
      REQUIRE(feature.attribute("class").toString() == stroke_class_name(s.cls));
      REQUIRE(feature.attribute("cells").toInt() == s.cells);
      REQUIRE(feature.attribute("mean_depth").isNull() == std::isnan(s.mean_depth_m));
      // A shapefile reads back its lines as multi-lines of one part.
      const QgsGeometry geometry = feature.geometry();
      const QgsPolylineXY line =
          geometry.isMultipart() ? geometry.asMultiPolyline().value(0) : geometry.asPolyline();
      REQUIRE(static_cast<std::size_t>(line.size()) == s.points.size());
      REQUIRE(line.back().x() == Approx(s.points.back().x));
    }
  }
  CHECK(k == core.strokes.size());
}

TEST_CASE("drawn strokes to a format without M values are written with a warning",
          "[plugin][outputs]") {
  const QString dem = kData + "/gorillas_utm32n.tif";
  QTemporaryDir dir;
  const auto warned = [](const RecordingFeedback& log) {
    return log.warnings.filter(QStringLiteral("keeps no M values")).size();
  };
  // Warned exactly when the layers read back have no M values (GDAL 3.10's GeoJSON driver says
  // it takes them, and drops them); GML keeps none in any GDAL the project meets. A SQLite file
  // in OGR's own flavour kept them in its lines and declared its layer 3D, which QGIS read as
  // LineStringZ: a layer with M values, no Z.
  int lost = 0;
  for (const char* format : {"geojson", "gml", "gpkg", "fgb", "sqlite"}) {
    CAPTURE(format);
    RecordingFeedback log;
    const Run run = runAlgorithm(dem, outputsAs(dir, format), dir, &log);
    INFO(run.error.toStdString());
    REQUIRE(run.ok);
    QgsVectorLayer written(run.results.value("FORMULATED").toString(), "f", "ogr");
    REQUIRE(written.featureCount() > 0);
    const bool measured = QgsWkbTypes::hasM(written.wkbType());
    CHECK_FALSE(QgsWkbTypes::hasZ(written.wkbType()));
    CHECK(warned(log) == (measured ? 0 : 2));  // one for each output
    lost += measured ? 0 : 1;
    CHECK((std::string(format) != "gml" || !measured));
    CHECK((std::string(format) != "sqlite" || measured));
  }
  CHECK(lost >= 1);
  RecordingFeedback exact;
  QVariantMap exactGml = outputsAs(dir, "gml");
  exactGml.insert("STROKES", 1);  // exact strokes carry no weights
  CHECK(runAlgorithm(dem, exactGml, dir, &exact).ok);
  CHECK(warned(exact) == 0);
}

TEST_CASE("a run waits while another writes its output, and a wait cancelled removes nothing",
          "[plugin][outputs][concurrency]") {
  // Two runs writing one GeoPackage at once: the second, failing, deleted the first one's file.
  // Now the second waits for the first (here, another process holding the output's lock) and,
  // cancelled while it waits, leaves the first one's output as it was.
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  REQUIRE(runAlgorithm(dem, {}, dir).ok);
  const QString factual = dir.filePath("factual.gpkg");
  QFile before(factual);
  REQUIRE(before.open(QIODevice::ReadOnly));
  const QByteArray bytes = before.readAll();
  before.close();
  class CancelWhenWaiting : public RecordingFeedback {
   public:
    void pushInfo(const QString& info) override {
      RecordingFeedback::pushInfo(info);
      if (info.contains(QStringLiteral("Waiting for another run"))) waited = true, cancel();
    }
    bool waited = false;
  } feedback;
  {
    // The other run: a process holding the output's lock (flock(1) locks as the tool does).
    const QString lock = dir.filePath(QStringLiteral(".factual.gpkg.lock"));
    QProcess otherRun;
    otherRun.start(QStringLiteral("flock"),
                   {QStringLiteral("-o"), lock, QStringLiteral("sleep"), QStringLiteral("60")});
    REQUIRE(otherRun.waitForStarted());
    for (int k = 0; k < 100 && !QFileInfo::exists(lock); ++k) QThread::msleep(20);
    QThread::msleep(200);
    const Run second = runAlgorithm(dem, {{"AZIMUTH", 0}}, dir, &feedback);
    CHECK(feedback.waited);
    CHECK_FALSE(second.ok);
    otherRun.kill();
    otherRun.waitForFinished();
  }
  QFile after(factual);
  REQUIRE(after.open(QIODevice::ReadOnly));
  CHECK(after.readAll() == bytes);
  // Free again, the next run writes it.
  REQUIRE(runAlgorithm(dem, {{"AZIMUTH", 0}}, dir).ok);
  CHECK_FALSE(QFileInfo::exists(dir.filePath(".factual.gpkg.lock")));
}
