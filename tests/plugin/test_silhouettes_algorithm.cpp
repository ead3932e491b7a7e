// The Silhouettes algorithm run headless on real DEMs: features, fields, CRS and figures equal
// the core's; bad input ends in a clear QgsProcessingException, never a crash.
#include <gdal.h>
#include <ogr_api.h>
#include <ogr_srs_api.h>
#include <qgsapplication.h>
#include <qgsfeatureiterator.h>
#include <qgsprocessingcontext.h>
#include <qgsprocessingfeedback.h>
#include <qgsprocessingparameters.h>
#include <qgsprocessingprovider.h>
#include <qgsprocessingregistry.h>
#include <qgsprocessingutils.h>
#include <qgsrasterblock.h>
#include <qgsrasterdataprovider.h>
#include <qgsrasterlayer.h>
#include <qgsrasterrange.h>
#include <qgsvectorlayer.h>
#include <sys/resource.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <csignal>
#include <functional>
#include <memory>

#include "dem_reader.h"
#include "diagnostics.h"
#include "drape.h"
#include "gdal_test_support.h"
#include "gpkg_index_check.h"
#include "plan_oblique.h"
#include "profile_plot.h"
#include "provider.h"
#include "pstrokes.h"
#include "qgis_compat.h"
#include "raster_grid.h"
#include "silhouettes.h"
#include "translation.h"
#include "visibility.h"

using namespace tsk;

namespace {

// Oriented profiles of a raster for a view, read window by window as a run reads them.
struct ViewStrips {
  DemSource source;
  StripLoader loader;
  ViewStrips(plugin::RasterGrid& grid, double azimuth)
      : source(grid.source(azimuth)), loader(source.frame, source.read) {}
};

// The lowest height of a raster read window by window, as a plan-oblique run reads it first.
double lowestOf(plugin::RasterGrid& grid) {
  const DemSource dem = grid.source(90);
  return dem_lowest_height(dem.frame.dem_rows, dem.frame.dem_cols, dem.read);
}

const QString kData = QStringLiteral(TSK_TEST_DATA);

QgsProcessingAlgorithm* algorithm() {
  static bool registered = false;
  if (!registered) {
    QgsApplication::processingRegistry()->addProvider(new plugin::TerrainSketchProvider());
    registered = true;
  }
  const QgsProcessingAlgorithm* alg = QgsApplication::processingRegistry()->algorithmById(
      QStringLiteral("terrainsketch:silhouettes"));
  REQUIRE(alg != nullptr);
  return alg->create();
}

// Keeps what the algorithm writes to the log.
class RecordingFeedback : public QgsProcessingFeedback {
 public:
  void reportError(const QString& error, bool fatal) override {
    errors << error;
    QgsProcessingFeedback::reportError(error, fatal);
  }
  void pushWarning(const QString& warning) override { warnings << warning; }
  QStringList errors;
  QStringList warnings;
};

struct Run {
  bool ok = false;
  QVariantMap results;
  QString error;
};

// Runs algorithm `id` with `extra` parameters on top of INPUT/BAND and outputs in `dir`.
// A memory output's layer stays in `context`, if given.
Run runAlgorithm(const QString& input, const QVariantMap& extra, const QTemporaryDir& dir,
                 RecordingFeedback* feedback = nullptr,
                 const QString& id = QStringLiteral("silhouettes"),
                 QgsProcessingContext* context = nullptr) {
  algorithm();  // registers the provider
  std::unique_ptr<QgsProcessingAlgorithm> alg(
      QgsApplication::processingRegistry()->algorithmById("terrainsketch:" + id)->create());
  QVariantMap params{{"INPUT", input},
                     {"BAND", 1},
                     {"FACTUAL", dir.filePath("factual.gpkg")},
                     {"FORMULATED", dir.filePath("formulated.gpkg")},
                     {"OUTPUT", dir.filePath(id == "profileplot" ? "out.gpkg" : "out.tif")}};
  for (auto it = extra.begin(); it != extra.end(); ++it) params.insert(it.key(), it.value());
  QgsProcessingContext ownContext;
  RecordingFeedback defaultFeedback;
  RecordingFeedback* log = feedback ? feedback : &defaultFeedback;
  Run run;
  run.results = alg->run(params, context ? *context : ownContext, log, &run.ok);
  run.error = log->errors.join('\n');
  return run;
}

// While alive, this process's files are limited to `bytes`: writes past it fail (EFBIG) as they
// would on a full disk, SIGXFSZ ignored meanwhile.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    REQUIRE(getrlimit(RLIMIT_FSIZE, &mBefore) == 0);
    mHandler = std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{bytes, mBefore.rlim_max};
    REQUIRE(setrlimit(RLIMIT_FSIZE, &limit) == 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &mBefore);
    std::signal(SIGXFSZ, mHandler);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit mBefore{};
  void (*mHandler)(int) = SIG_DFL;
};

// Both line outputs in `dir`, as files of `format` ("gpkg", "shp", ...).
QVariantMap outputsAs(const QTemporaryDir& dir, const char* format) {
  return {{"FACTUAL", dir.filePath(QStringLiteral("factual.%1").arg(format))},
          {"FORMULATED", dir.filePath(QStringLiteral("formulated.%1").arg(format))}};
}

// Runs the core directly on the same file through the CLI's GDAL reader, as the CLI does.
SilhouetteResult coreResult(const QString& file, double azimuth, Geometry geometry) {
  io::DemOptions options;
  options.azimuth_deg = azimuth;
  const io::Dem dem = io::read_dem(file.toStdString(), options);
  SilhouetteParams params;
  params.view.azimuth_deg = azimuth;
  params.geometry = geometry;
  return run_silhouettes(dem.oriented, dem.frame, dem.geotransform, params, {}, dem.lowest_height);
}

}  // namespace

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
    // QGIS wrote them without an index; the algorithm then built it in bulk.
    test::check_spatial_index(
        run.results.value("FACTUAL").toString().section('|', 0, 0).toStdString(), "factual");
    test::check_spatial_index(
        run.results.value("FORMULATED").toString().section('|', 0, 0).toStdString(), "formulated");
    QgsFeatureIterator fo = formulated.getFeatures();
    while (fo.nextFeature(feature)) {
      REQUIRE(feature.attribute("class").toString() == "formulated");
      REQUIRE(feature.attribute("mean_depth").isNull());
    }
  }
}

TEST_CASE("bad input ends in a clear message, never a crash", "[plugin][robustness]") {
  QTemporaryDir dir;
  const QString sample = kData + "/jacksboro_utm16n.tif";
  struct Bad {
    QString input;
    QVariantMap extra;
    const char* message;
  };
  const Bad cases[] = {
      {kData + "/jacksboro_geo.tif", {}, "geographic CRS"},
      {sample, {{"BAND", 2}}, "Band 2 does not exist"},
      {sample, {{"CTRL_COL", 12.5}}, "control point"},
      {dir.filePath("missing.tif"), {}, ""},
  };
  for (const Bad& b : cases) {
    CAPTURE(b.input.toStdString(), b.message);
    const Run run = runAlgorithm(b.input, b.extra, dir);
    CHECK_FALSE(run.ok);
    CHECK_THAT(run.error.toStdString(), Catch::Contains(b.message));
  }
}

TEST_CASE("a raster without CRS runs with a warning in the log", "[plugin]") {
  RecordingFeedback log;
  QTemporaryDir dir;
  const Run run = runAlgorithm(kData + "/bei_5m_local.tif", {}, dir, &log);
  CHECK(run.ok);
  CHECK(log.warnings.join(' ').contains("no CRS"));
}

TEST_CASE("an undeclared fill value among the heights gets a warning", "[plugin]") {
  QTemporaryDir dir;
  const auto filled = [](int band, int r, int c) {
    return c < 6 ? -32768.0f : test::hill(band, r, c);
  };
  const QString undeclared = dir.filePath("filled.tif"), declared = dir.filePath("declared.tif");
  test::write_tiff(undeclared.toStdString(), 40, 40, 1, filled, test::kNorthUp, 32616);
  test::write_tiff(declared.toStdString(), 40, 40, 1, filled, test::kNorthUp, 32616, -32768.0);
  RecordingFeedback log;
  REQUIRE(runAlgorithm(undeclared, {}, dir, &log).ok);
  CHECK(log.warnings.join(' ').contains("-32768, a common fill value"));
  RecordingFeedback quiet;
  REQUIRE(runAlgorithm(declared, {}, dir, &quiet).ok);
  CHECK_FALSE(quiet.warnings.join(' ').contains("fill value"));
}

TEST_CASE("heights that rise more than any terrain get a warning", "[plugin]") {
  // The hill in millimetres: 300 000 over a raster 400 m across.
  QTemporaryDir dir;
  const QString millimetres = dir.filePath("mm.tif"), metres = dir.filePath("m.tif");
  test::write_tiff(
      millimetres.toStdString(), 40, 40, 1,
      [](int band, int r, int c) { return 1000 * test::hill(band, r, c); }, test::kNorthUp, 32616);
  test::write_tiff(metres.toStdString(), 40, 40, 1, test::hill, test::kNorthUp, 32616);
  RecordingFeedback log, quiet;
  REQUIRE(runAlgorithm(millimetres, {}, dir, &log).ok);
  CHECK(log.warnings.join(' ').contains("more than any terrain"));
  REQUIRE(runAlgorithm(metres, {}, dir, &quiet).ok);
  CHECK_FALSE(quiet.warnings.join(' ').contains("more than any terrain"));
}

TEST_CASE("a CRS in feet runs with a warning that heights must be in feet too", "[plugin]") {
  QTemporaryDir dir;
  const QString feet = dir.filePath("feet.tif");
  const double geotransform[6] = {2000000, 30, 0, 700000, 0, -30};
  test::write_tiff(feet.toStdString(), 40, 40, 1, test::hill, geotransform, 2264);
  RecordingFeedback log;
  const Run run = runAlgorithm(feet, {}, dir, &log);
  CHECK(run.ok);
  CHECK(log.warnings.join(' ').contains("not the metre"));
  RecordingFeedback metres;
  REQUIRE(runAlgorithm(kData + "/gorillas_utm32n.tif", {}, dir, &metres).ok);
  CHECK_FALSE(metres.warnings.join(' ').contains("not the metre"));
}

// Cancels the run once progress reaches `at` percent.
class CancelAt : public RecordingFeedback {
 public:
  explicit CancelAt(double at, std::function<void()> onCancel = {}) {
    connect(this, &QgsFeedback::progressChanged, this, [this, at, onCancel](double progress) {
      if (progress < at || isCanceled()) return;
      if (onCancel) onCancel();
      cancel();
    });
  }
};

// The layer names of a vector file.
QStringList layerNames(const QString& path) {
  QStringList names;
  GDALDatasetH ds =
      GDALOpenEx(path.toUtf8().constData(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr);
  if (!ds) return names;
  for (int k = 0; k < GDALDatasetGetLayerCount(ds); ++k)
    names << QString::fromUtf8(OGR_L_GetName(GDALDatasetGetLayer(ds, k)));
  GDALClose(ds);
  return names;
}

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
    CHECK(run.error.contains("File too large"));
    CHECK(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    CHECK(runAlgorithm(kData + "/jacksboro_utm16n.tif", output, dir, nullptr, id).ok);
    QFile::remove(dir.filePath("out.tif"));
    QFile::remove(dir.filePath("out.html"));
  }
}

TEST_CASE("strokes written before a cancel are removed with their files", "[plugin][outputs]") {
  QTemporaryDir dir;
  // Strokes go to the outputs as they complete: halfway, the shapefile holds some.
  qint64 shapefileBytes = 0;
  CancelAt feedback(50, [&] { shapefileBytes = QFileInfo(dir.filePath("factual.shp")).size(); });
  const Run run =
      runAlgorithm(kData + "/gorillas_utm32n.tif",
                   {{"STRIPS", 17}, {"FACTUAL", dir.filePath("factual.shp")}}, dir, &feedback);
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("Cancelled"));
  CHECK(shapefileBytes > 1000);
  CHECK(QDir(dir.path()).entryList(QDir::Files).isEmpty());
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
  const Case cases[] = {
      {"silhouettes", gpkg, {{"FACTUAL", gpkg}}},
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
          "dem.gpkg dem.tif dem.tif.aux.xml");
  }
  // Beside the raster, in a file of their own, the outputs are written.
  const Run run = runAlgorithm(gpkg, {}, dir);
  INFO(run.error.toStdString());
  CHECK(run.ok);
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

TEST_CASE("every algorithm and parameter has help, and numbers show what they can take",
          "[plugin]") {
  algorithm();  // registers the provider
  const QgsProcessingProvider* provider =
      QgsApplication::processingRegistry()->providerById(QStringLiteral("terrainsketch"));
  REQUIRE(provider != nullptr);
  REQUIRE(provider->algorithms().size() == 7);
  for (const QgsProcessingAlgorithm* alg : provider->algorithms()) {
    CAPTURE(alg->id().toStdString());
    CHECK(alg->shortHelpString().size() > 100);
    for (const QgsProcessingParameterDefinition* parameter : alg->parameterDefinitions()) {
      CAPTURE(parameter->name().toStdString());
      CHECK(parameter->help().size() > 10);
      const auto* number = dynamic_cast<const QgsProcessingParameterNumber*>(parameter);
      if (!number || number->dataType() != plugin::kDoubleNumber) continue;
      // The widget rounds to its decimals: both the default and the minimum must survive.
      const int decimals = number->metadata()
                               .value(QStringLiteral("widget_wrapper"))
                               .toMap()
                               .value(QStringLiteral("decimals"), 6)
                               .toInt();
      CHECK(decimals <= 3);
      const double scale = std::pow(10.0, decimals);
      for (const double value : {number->defaultValue().toDouble(), number->minimum()})
        CHECK(std::round(value * scale) / scale == Approx(value).margin(1e-12));
    }
  }
}

TEST_CASE("the German translation loads for the de locale", "[plugin][i18n]") {
  // The code under test is linked into this binary, so name the built plugin's i18n folder.
  const QString folder = QStringLiteral(TSK_PLUGIN_DIR "/i18n");
  REQUIRE(plugin::installTranslation(QStringLiteral("de"), folder));
  const plugin::TerrainSketchProvider provider;
  CHECK(provider.name() == QStringLiteral("Geländeskizze"));
  std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm());
  CHECK(alg->displayName() == QStringLiteral("Silhouetten (faktisch und formuliert)"));
  CHECK(alg->parameterDefinition("VE")->description() == QStringLiteral("Überhöhung"));
  plugin::removeTranslation();
  CHECK(provider.name() == QStringLiteral("Terrain sketch"));
  CHECK_FALSE(plugin::installTranslation(QStringLiteral("xx"), folder));
}

TEST_CASE("the classification raster holds the core's stage counts", "[plugin][diagnostics]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runAlgorithm(dem, {}, dir, nullptr, QStringLiteral("classification"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
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

TEST_CASE("the row slope map equals the core's", "[plugin][diagnostics]") {
  QTemporaryDir dir;
  const QString dem = kData + "/volcano.tif";
  const Run run = runAlgorithm(dem, {{"AZIMUTH", 30}}, dir, nullptr, QStringLiteral("rowslope"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  io::DemOptions options;
  options.azimuth_deg = 30;
  const io::Dem core = io::read_dem(dem.toStdString(), options);
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

TEST_CASE("the profile plot algorithm draws the core's lines", "[plugin][profile plot]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runAlgorithm(dem, {{"EVERY", 12}}, dir, nullptr, QStringLiteral("profileplot"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  io::DemOptions options;
  const io::Dem core = io::read_dem(dem.toStdString(), options);
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

TEST_CASE("the slope filter diagram is an HTML page with the filter drawn",
          "[plugin][filter diagram]") {
  QTemporaryDir dir;
  const Run run = runAlgorithm(kData + "/volcano.tif",
                               {{"CTRL_COL", 6}, {"OUTPUT", dir.filePath("filter.html")}}, dir,
                               nullptr, QStringLiteral("filterdiagram"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  QFile file(run.results.value("OUTPUT").toString());
  REQUIRE(file.open(QIODevice::ReadOnly));
  const QString html = QString::fromUtf8(file.readAll());
  CHECK(html.startsWith("<!DOCTYPE html>"));
  CHECK(html.contains("<polygon id=\"removal\""));
  CHECK(html.contains("control point (6 %, 3.6 %)"));
}

TEST_CASE("the drape algorithm equals the core's drape", "[plugin][drape]") {
  QTemporaryDir dir;
  const QString dem = kData + "/volcano.tif";
  // Drape the DEM onto itself: draped values are heights of visible cells.
  const Run run =
      runAlgorithm(dem, {{"SOURCE", dem}, {"AZIMUTH", 180}}, dir, nullptr, QStringLiteral("drape"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  io::DemOptions options;
  options.azimuth_deg = 180;
  const io::Dem core = io::read_dem(dem.toStdString(), options);
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

TEST_CASE("the P-stroke algorithm draws the core's P-strokes", "[plugin][pstrokes]") {
  QTemporaryDir dir;
  const QString dem = kData + "/jacksboro_utm16n.tif";
  const Run run = runAlgorithm(dem, {{"GEOMETRY", 0}, {"OUTPUT", dir.filePath("p.gpkg")}}, dir,
                               nullptr, QStringLiteral("pstrokes"));
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  io::DemOptions options;
  const io::Dem core = io::read_dem(dem.toStdString(), options);
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

TEST_CASE("a GDAL layer's file is read straight through GDAL, with the provider's heights",
          "[plugin][strips]") {
  const QString dem = kData + "/gorillas_utm32n.tif";  // with a nodata border
  QgsRasterLayer plain(dem, "plain", "gdal");
  QgsRasterLayer masked(dem, "masked", "gdal");
  // A nodata range set in QGIS, holding no height: the provider must read it, same heights.
  masked.dataProvider()->setUserNoDataValue(1, {QgsRasterRange(-1e30, -1e29)});
  QTemporaryDir dir;
  const QString scaledPath = dir.filePath("scaled.tif");
  {
    GDALDatasetH source = GDALOpen(dem.toUtf8().constData(), GA_ReadOnly);
    GDALDatasetH copy =
        GDALCreateCopy(GDALGetDriverByName("GTiff"), scaledPath.toUtf8().constData(), source, 0,
                       nullptr, nullptr, nullptr);
    GDALSetRasterScale(GDALGetRasterBand(copy, 1), 2.0);
    GDALSetRasterOffset(GDALGetRasterBand(copy, 1), 100.0);
    GDALClose(copy);
    GDALClose(source);
  }
  // Its values x 2 + 100: read straight, the scale and offset are applied as the provider does.
  QgsRasterLayer scaled(scaledPath, "scaled", "gdal");
  QgsRasterLayer scaledMasked(scaledPath, "scaled, masked", "gdal");
  scaledMasked.dataProvider()->setUserNoDataValue(1, {QgsRasterRange(-1e30, -1e29)});
  const QgsCoordinateTransformContext transforms;
  plugin::RasterGrid direct(&plain, 1, transforms), provider(&masked, 1, transforms);
  plugin::RasterGrid scaledDirect(&scaled, 1, transforms);
  plugin::RasterGrid scaledProvider(&scaledMasked, 1, transforms);
  CHECK(direct.readsFileDirectly());
  CHECK_FALSE(provider.readsFileDirectly());
  CHECK(scaledDirect.readsFileDirectly());
  CHECK_FALSE(scaledProvider.readsFileDirectly());
  const auto same = [](const HeightGrid& a, const HeightGrid& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      const float x = a.data()[k], y = b.data()[k];
      if (!(x == y || (std::isnan(x) && std::isnan(y)))) return false;
    }
    return true;
  };
  CHECK(lowestOf(direct) == lowestOf(provider));
  CHECK(lowestOf(scaledDirect) == lowestOf(scaledProvider));
  CHECK(lowestOf(scaledDirect) == Approx(2 * lowestOf(direct) + 100));
  for (auto [straight, through] :
       {std::pair{&direct, &provider}, std::pair{&scaledDirect, &scaledProvider}}) {
    for (double az : {90.0, 0.0, 45.0}) {
      CAPTURE(straight == &scaledDirect, az);
      ViewStrips straightStrips(*straight, az), throughStrips(*through, az);
      const std::size_t profiles = straightStrips.source.frame.profiles;
      HeightGrid a, b;
      std::size_t nodata = 0;
      for (std::size_t first = 0; first < profiles; first += 17) {
        const std::size_t count = std::min<std::size_t>(19, profiles - first);
        straightStrips.loader.load(first, count, a);
        throughStrips.loader.load(first, count, b);
        REQUIRE(same(a, b));
        nodata += static_cast<std::size_t>(
            std::count_if(a.data(), a.data() + a.size(), [](float z) { return std::isnan(z); }));
      }
      CHECK(nodata > 0);
    }
  }
  ViewStrips directRows(direct, 90), scaledRows(scaledDirect, 90);  // profiles are the rows
  HeightGrid metres, values;
  directRows.loader.load(0, directRows.source.frame.profiles, metres);
  scaledRows.loader.load(0, scaledRows.source.frame.profiles, values);
  REQUIRE(metres.size() == values.size());
  for (std::size_t k = 0; k < metres.size(); ++k) {
    const float z = metres.data()[k];
    if (is_data(z)) REQUIRE(values.data()[k] == static_cast<float>(2.0 * z + 100.0));
  }
}

TEST_CASE("a raster that fails to read partway fails the run and leaves no output",
          "[plugin][outputs][robustness]") {
  QTemporaryDir dir;
  const std::string folder = dir.path().toStdString();
  test::write_tiff(folder + "/top.tif", 40, 40, 1, test::hill, test::kNorthUp, 32616);
  test::write_half_missing_vrt(folder + "/dem.vrt", "top.tif");
  const QStringList before = QDir(dir.path()).entryList(QDir::Files);
  for (const char* format : {"gpkg", "shp"}) {
    CAPTURE(format);
    const Run run =
        runAlgorithm(dir.filePath("dem.vrt"),
                     {{"STRIPS", 5},
                      {"FACTUAL", dir.filePath(QStringLiteral("factual.%1").arg(format))},
                      {"FORMULATED", dir.filePath(QStringLiteral("formulated.%1").arg(format))}},
                     dir);
    CHECK_FALSE(run.ok);
    CHECK(run.error.contains("gone.tif"));
    CHECK(QDir(dir.path()).entryList(QDir::Files) == before);
  }
}

TEST_CASE("a DEM too large to hold whole is refused by the algorithms that need it whole",
          "[plugin][robustness]") {
  QTemporaryDir dir;
  test::write_huge_vrt(dir.filePath("huge.vrt").toStdString());
  for (const char* id : {"classification", "rowslope", "profileplot"}) {
    CAPTURE(id);
    const Run run = runAlgorithm(dir.filePath("huge.vrt"), {}, dir, nullptr, id);
    CHECK_FALSE(run.ok);
    CHECK(run.error.contains("too large"));
    CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"huge.vrt"});
  }
}

TEST_CASE("a rotated or south-up raster is read as QGIS warps it, through its provider",
          "[plugin][robustness]") {
  QTemporaryDir dir;
  const double rotated[6] = {500000, 10, 2, 4000000, 2, -10};
  const double southUp[6] = {500000, 10, 0, 3999600, 0, 10};
  for (const double* transform : {rotated, southUp}) {
    const QString path = dir.filePath(transform == rotated ? "rotated.tif" : "south_up.tif");
    CAPTURE(path.toStdString());
    test::write_tiff(path.toStdString(), 40, 40, 1, test::hill, transform, 32616);
    QgsRasterLayer layer(path, "warped", "gdal");
    REQUIRE(layer.isValid());
    CHECK_FALSE(plugin::RasterGrid(&layer, 1, QgsCoordinateTransformContext()).readsFileDirectly());
    const Run run = runAlgorithm(path, {}, dir);
    INFO(run.error.toStdString());
    REQUIRE(run.ok);
    CHECK(run.results.value("FACTUAL_STROKES").toDouble() > 0);
  }
  // A plain turned by QGIS: the cells it adds around it (0, as the file has no nodata value) are
  // no data, not a 500 m drop along the plain's edges.
  const QString plain = dir.filePath("rotated_plain.tif");
  test::write_tiff(
      plain.toStdString(), 40, 40, 1, [](int, int, int) { return 500.0f; }, rotated, 32616);
  QgsRasterLayer layer(plain, "rotated plain", "gdal");
  plugin::RasterGrid grid(&layer, 1, QgsCoordinateTransformContext());
  CHECK(grid.notes().join(' ').contains("rotated"));
  ViewStrips rows(grid, 90);
  HeightGrid heights;
  rows.loader.load(0, rows.source.frame.profiles, heights);
  const auto nodata = std::count_if(heights.data(), heights.data() + heights.size(),
                                    [](float z) { return std::isnan(z); });
  CHECK(nodata > 0);
  CHECK(std::all_of(heights.data(), heights.data() + heights.size(),
                    [](float z) { return std::isnan(z) || z == 500.0f; }));
  const Run run = runAlgorithm(plain, {}, dir);
  REQUIRE(run.ok);
  CHECK(run.results.value("FACTUAL_STROKES").toDouble() == 0);
  CHECK(run.results.value("FORMULATED_STROKES").toDouble() == 0);
}

TEST_CASE("the band asked for is the band read from the file", "[plugin][strips]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("two_bands.tif");
  test::write_tiff(
      path.toStdString(), 40, 40, 2, [](int b, int r, int c) { return test::hill(b, r, c) * b; },
      test::kNorthUp, 32616);
  QgsRasterLayer layer(path, "two", "gdal");
  REQUIRE(layer.isValid());
  plugin::RasterGrid first(&layer, 1, QgsCoordinateTransformContext());
  plugin::RasterGrid second(&layer, 2, QgsCoordinateTransformContext());
  REQUIRE(second.readsFileDirectly());
  HeightGrid a, b;
  ViewStrips firstRows(first, 90), secondRows(second, 90);
  firstRows.loader.load(0, 40, a);
  secondRows.loader.load(0, 40, b);
  REQUIRE(a.size() == b.size());
  std::size_t compared = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a.data()[k] > 1) {
      REQUIRE(b.data()[k] == 2 * a.data()[k]);
      ++compared;
    }
  }
  CHECK(compared > 100);
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
