// Reading a QGIS raster layer (RasterGrid): bad input ends in a clear message, notes become
// warnings, files are read straight through GDAL with the provider's heights, rotated rasters.
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

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

TEST_CASE("float's fill values are read as nodata, with a warning", "[plugin]") {
  // A strip of float's highest value, undeclared, stood as a wall that hid the rest of the hill.
  QTemporaryDir dir, declaredDir;
  const auto filled = [](float fill) {
    return [fill](int band, int r, int c) { return c < 6 ? fill : test::hill(band, r, c); };
  };
  const QString undeclared = dir.filePath("filled.tif");
  const QString declared = declaredDir.filePath("declared.tif");
  test::write_tiff(undeclared.toStdString(), 40, 40, 1, filled(3.4028235e38f), test::kNorthUp,
                   32616);
  test::write_tiff(declared.toStdString(), 40, 40, 1, filled(-1.0f), test::kNorthUp, 32616, -1.0);
  RecordingFeedback log;
  const QVariantMap fromWest{{"AZIMUTH", 270}};
  REQUIRE(runAlgorithm(undeclared, fromWest, dir, &log).ok);
  CHECK(log.warnings.join(' ').contains("taken as no data"));
  REQUIRE(runAlgorithm(declared, fromWest, declaredDir).ok);
  long long strokes = 0;
  for (const QString& name : {QStringLiteral("factual.gpkg"), QStringLiteral("formulated.gpkg")}) {
    const QgsVectorLayer read(dir.filePath(name), "read", "ogr");
    const QgsVectorLayer oracle(declaredDir.filePath(name), "oracle", "ogr");
    CAPTURE(name.toStdString());
    CHECK(read.featureCount() == oracle.featureCount());
    CHECK(read.extent() == oracle.extent());
    strokes += oracle.featureCount();
  }
  CHECK(strokes > 0);
  // Read straight through GDAL, or through QGIS's provider (which a nodata range set in QGIS
  // makes the plugin use), the strip holds no heights, as where it is declared nodata.
  QgsRasterLayer plain(undeclared, "plain", "gdal"), masked(undeclared, "masked", "gdal");
  QgsRasterLayer declaredLayer(declared, "declared", "gdal");
  masked.dataProvider()->setUserNoDataValue(1, {QgsRasterRange(-1e20, -1e19)});
  const QgsCoordinateTransformContext transforms;
  plugin::RasterGrid direct(&plain, 1, transforms), provider(&masked, 1, transforms);
  plugin::RasterGrid oracle(&declaredLayer, 1, transforms);
  REQUIRE(direct.readsFileDirectly());
  REQUIRE_FALSE(provider.readsFileDirectly());
  const HeightGrid expected = viewHeights(oracle, 90);
  CHECK(sameHeights(viewHeights(direct, 90), expected));
  CHECK(sameHeights(viewHeights(provider, 90), expected));
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
  CHECK(lowestOf(direct) == lowestOf(provider));
  CHECK(lowestOf(scaledDirect) == lowestOf(scaledProvider));
  CHECK(lowestOf(scaledDirect) == Approx(2 * lowestOf(direct) + 100));
  for (auto [straight, through] :
       {std::pair{&direct, &provider}, std::pair{&scaledDirect, &scaledProvider}}) {
    for (double az : {90.0, 0.0, 45.0}) {
      CAPTURE(straight == &scaledDirect, az);
      ViewStrips straightStrips(*straight, az), throughStrips(*through, az);
      const std::size_t profiles = straightStrips.frame.profiles;
      HeightGrid a, b;
      std::size_t nodata = 0;
      for (std::size_t first = 0; first < profiles; first += 17) {
        const std::size_t count = std::min<std::size_t>(19, profiles - first);
        straightStrips.loader.load(first, count, a);
        throughStrips.loader.load(first, count, b);
        REQUIRE(sameHeights(a, b));
        nodata += static_cast<std::size_t>(
            std::count_if(a.data(), a.data() + a.size(), [](float z) { return std::isnan(z); }));
      }
      CHECK(nodata > 0);
    }
  }
  ViewStrips directRows(direct, 90), scaledRows(scaledDirect, 90);  // profiles are the rows
  HeightGrid metres, values;
  directRows.loader.load(0, directRows.frame.profiles, metres);
  scaledRows.loader.load(0, scaledRows.frame.profiles, values);
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
  rows.loader.load(0, rows.frame.profiles, heights);
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

TEST_CASE("an RGB image is refused before the run, in the dialog's check", "[plugin][robustness]") {
  QTemporaryDir dir;
  const QString rgb = dir.filePath("rgb.tif");
  test::write_tiff(
      rgb.toStdString(), 40, 40, 3, [](int b, int r, int c) { return 100.f * b + r + c; },
      test::kNorthUp, 32616);
  test::mark_rgb(rgb.toStdString());
  std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm()->create());
  QgsProcessingContext context;
  QString message;
  const QVariantMap parameters = {{"INPUT", rgb},
                                  {"BAND", 1},
                                  {"FACTUAL", dir.filePath("f.gpkg")},
                                  {"FORMULATED", dir.filePath("m.gpkg")}};
  CHECK_FALSE(alg->checkParameterValues(parameters, context, &message));
  INFO(message.toStdString());
  CHECK(message.contains("colour channel"));
  const Run run = runAlgorithm(rgb, {}, dir);
  CHECK_FALSE(run.ok);
  CHECK(run.error.contains("colour channel"));
}

TEST_CASE("a raster whose georeferencing places no cell is refused for it",
          "[plugin][robustness]") {
  // QGIS blamed the cell sizes ("got nan x 10", "got 10 x 0") of rasters whose corners are not a
  // number or lie so far out that the extent's height rounds to nothing.
  QTemporaryDir dir;
  const double nanOrigin[6] = {std::nan(""), 10, 0, 4000000, 0, -10};
  const double farOrigin[6] = {500000, 10, 0, 1e300, 0, -10};
  const struct {
    const char* name;
    const double* geotransform;
    const char* message;
  } cases[] = {{"nan_origin.tif", nanOrigin, "not a finite number"},
               {"far_origin.tif", farOrigin, "too far for coordinates"}};
  for (const auto& c : cases) {
    const QString path = dir.filePath(c.name);
    test::write_tiff(path.toStdString(), 40, 40, 1, test::hill, c.geotransform, 32616);
    std::unique_ptr<QgsProcessingAlgorithm> alg(algorithm()->create());
    QgsProcessingContext context;
    QString message;
    const QVariantMap parameters = {{"INPUT", path},
                                    {"FACTUAL", dir.filePath("f.gpkg")},
                                    {"FORMULATED", dir.filePath("m.gpkg")}};
    CHECK_FALSE(alg->checkParameterValues(parameters, context, &message));
    CAPTURE(message.toStdString());
    CHECK(message.contains(c.message));
    CHECK(message.contains("gdal_edit.py -a_ullr"));
  }
}

TEST_CASE("reading a raster without a valid cell prints no GDAL errors", "[plugin]") {
  // GDAL printed "no valid pixels found in sampling" for each of our statistics calls, on top of
  // the one QGIS prints as it loads such a layer; the run's warning says what is wrong.
  QTemporaryDir dir;
  const QString path = dir.filePath("empty.tif");
  test::write_tiff(
      path.toStdString(), 40, 40, 1, [](int, int, int) { return -1.0f; }, test::kNorthUp, 32616,
      -1.0);
  QgsRasterLayer layer(path, "empty", "gdal");
  REQUIRE(layer.isValid());
  static int printed = 0;
  printed = 0;
  CPLPushErrorHandler([](CPLErr, CPLErrorNum, const char*) { ++printed; });
  const plugin::RasterGrid grid(&layer, 1, QgsCoordinateTransformContext());
  CPLPopErrorHandler();
  CHECK(printed == 0);
  CHECK(grid.readsFileDirectly());
}
