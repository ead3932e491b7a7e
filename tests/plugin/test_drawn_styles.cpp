// What a map designer gets in QGIS from drawn strokes: LineString M layers that the drawn styles
// draw tapered at a real map scale, and the A3 print layout template.
#include <qgsexpressioncontextutils.h>
#include <qgslayout.h>
#include <qgslayoutitemlegend.h>
#include <qgslayoutitemmap.h>
#include <qgslayoutitemregistry.h>
#include <qgslayoutpagecollection.h>
#include <qgslinestring.h>
#include <qgsmaprenderersequentialjob.h>
#include <qgsproject.h>
#include <qgsreadwritecontext.h>
#include <qgssinglesymbolrenderer.h>
#include <qgssymbol.h>

#include <QDomDocument>
#include <QFile>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

#include "plugin/tapered_line.h"
#include "plugin_test_support.h"

using namespace tsk::plugin_test;

namespace {

// A layer drawn over `extent`'s centre at 1:`scale` and `dpi`, `size` pixels square, on white,
// with a style from the plugin folder.
QImage render(QgsVectorLayer& layer, const QString& style, double scale, double dpi = 96,
              int size = 800) {
  bool ok = false;
  layer.loadNamedStyle(QStringLiteral(TSK_PLUGIN_DIR "/styles/") + style, ok);
  REQUIRE(ok);
  QgsMapSettings settings;
  settings.setLayers({&layer});
  settings.setDestinationCrs(layer.crs());
  settings.setOutputDpi(dpi);
  settings.setOutputSize(QSize(size, size));
  const QgsPointXY centre = layer.extent().center();
  const double half = size / dpi * 0.0254 * scale / 2;  // metres across half the picture
  settings.setExtent(
      QgsRectangle(centre.x() - half, centre.y() - half, centre.x() + half, centre.y() + half));
  settings.setBackgroundColor(Qt::white);
  QgsExpressionContext context;
  context.appendScope(QgsExpressionContextUtils::mapSettingsScope(settings));
  settings.setExpressionContext(context);
  QgsMapRendererSequentialJob job(settings);
  job.start();
  job.waitForFinished();
  return job.renderedImage();
}

// Dark pixels of a layer drawn over its extent at 1:`scale` (96 dpi).
long long darkPixels(QgsVectorLayer& layer, const QString& style, double scale) {
  const QImage image = render(layer, style, scale);
  long long dark = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) dark += qGray(image.pixel(x, y)) < 128;
  return dark;
}

// The ink across column x: how many pixels' worth of it, anti-aliased edges counted in part.
double inkAcross(const QImage& image, int x) {
  double ink = 0;
  for (int y = 0; y < image.height(); ++y) ink += (255 - qGray(image.pixel(x, y))) / 255.0;
  return ink;
}

// One straight west-east drawn stroke, 4 km long, whose M values change by halves of it: a flat
// stretch of each weight between vertices of that weight.
std::unique_ptr<QgsVectorLayer> straightStroke(const std::vector<double>& weights) {
  auto layer = std::make_unique<QgsVectorLayer>(QStringLiteral("LineStringM?crs=EPSG:32616"),
                                                QStringLiteral("stroke"), QStringLiteral("memory"));
  QgsLineString line;
  const double step = 4000.0 / (2 * weights.size() - 1);
  for (std::size_t k = 0; k < 2 * weights.size(); ++k)
    line.addVertex(QgsPoint(500000 + step * k, 4000000, std::numeric_limits<double>::quiet_NaN(),
                            weights[k / 2]));  // a PointM: no z, an m
  QgsFeature feature;
  feature.setGeometry(QgsGeometry(line.clone()));
  QgsFeatureList features{feature};
  REQUIRE(layer->dataProvider()->addFeatures(features));
  layer->updateExtents();
  return layer;
}

}  // namespace

TEST_CASE("drawn strokes come out as LineString M and their styles draw them", "[plugin][drawn]") {
  QTemporaryDir dir;
  const Run run = runAlgorithm(kData + "/jacksboro_utm16n.tif", {}, dir);
  INFO(run.error.toStdString());
  REQUIRE(run.ok);
  QgsVectorLayer factual(run.results.value("FACTUAL").toString(), "f", "ogr");
  REQUIRE(factual.isValid());
  CHECK(factual.wkbType() == plugin::kLineStringM);
  QgsFeature feature;
  QgsFeatureIterator it = factual.getFeatures();
  REQUIRE(it.nextFeature(feature));
  const auto* line = qgsgeometry_cast<const QgsLineString*>(feature.geometry().constGet());
  REQUIRE(line != nullptr);
  for (int k = 0; k < line->numPoints(); ++k) {
    CHECK(line->mAt(k) > 0.0);
    CHECK(line->mAt(k) <= 1.0);
  }
  // At 1:50 000 the drawn style inks the strokes; thinner at 1:50 000 than the exact style's
  // full widths would be, never invisible.
  const long long drawn = darkPixels(factual, QStringLiteral("factual_drawn.qml"), 50000);
  const long long exact = darkPixels(factual, QStringLiteral("factual.qml"), 50000);
  CHECK(drawn > 2000);
  CHECK(drawn < exact * 2);
}

TEST_CASE("the drawn styles draw the width every vertex carries", "[plugin][drawn][taper]") {
  plugin::registerTaperedLine();
  const std::vector<double> weights = {0.2, 1.0, 0.45, 0.9, 0.3};
  auto layer = straightStroke(weights);
  // 1:50 000 at 300 dpi: 4.2 m a pixel, the 4 km stroke 945 pixels long; 0.7 mm is 8.3 pixels.
  const double dpi = 300, size = 1200, metresPerPixel = 0.0254 / dpi * 50000;
  const QImage image = render(*layer, QStringLiteral("factual_drawn.qml"), 50000, dpi, size);
  const double step = 4000.0 / (2 * weights.size() - 1);
  for (std::size_t k = 0; k < weights.size(); ++k) {
    // The middle of the flat stretch between the two vertices of weight k.
    const double east = (2 * k + 0.5) * step - 2000;
    const int column = static_cast<int>(std::lround(size / 2 + east / metresPerPixel));
    INFO("weight " << weights[k] << " at column " << column);
    CHECK(inkAcross(image, column) == Approx(0.7 / 25.4 * dpi * weights[k]).margin(0.6));
  }
}

TEST_CASE("without the plugin the drawn styles fall back to stepped lines", "[plugin][drawn]") {
  plugin::unregisterTaperedLine();
  auto layer = straightStroke({0.2, 1.0, 0.45, 0.9, 0.3});
  const double dpi = 300, size = 1200;
  const QImage image = render(*layer, QStringLiteral("factual_drawn.qml"), 50000, dpi, size);
  // QGIS dropped the unknown layer; the four steps draw, the widest at the stroke's largest
  // weight in its middle, where the plugin would draw 0.45 of it.
  const auto* renderer = dynamic_cast<QgsSingleSymbolRenderer*>(layer->renderer());
  REQUIRE(renderer != nullptr);
  CHECK(renderer->symbol()->symbolLayerCount() == 4);
  const double widest = 0.7 / 25.4 * dpi;
  CHECK(inkAcross(image, static_cast<int>(size / 2)) == Approx(widest).margin(1.0));
  plugin::registerTaperedLine();
  CHECK(dynamic_cast<QgsSingleSymbolRenderer*>(layer->renderer()) != nullptr);
  render(*layer, QStringLiteral("factual_drawn.qml"), 50000, dpi, size);
  CHECK(dynamic_cast<QgsSingleSymbolRenderer*>(layer->renderer())->symbol()->symbolLayerCount() ==
        5);
}

TEST_CASE("the A3 layout template holds the sketch map, a key, a north arrow and a scale bar",
          "[plugin][layout]") {
  QFile file(QStringLiteral(TSK_PLUGIN_DIR "/layouts/terrain_sketch_a3.qpt"));
  REQUIRE(file.open(QIODevice::ReadOnly));
  QDomDocument document;
  REQUIRE(document.setContent(&file));
  QgsProject project;
  QgsLayout layout(&project);
  bool ok = false;
  layout.loadFromTemplate(document, QgsReadWriteContext(), true, &ok);
  REQUIRE(ok);
  REQUIRE(layout.pageCollection()->pageCount() == 1);
  const QgsLayoutSize page = layout.pageCollection()->page(0)->pageSize();
  CHECK(page.width() == Approx(420));
  CHECK(page.height() == Approx(297));
  const auto* map = qobject_cast<QgsLayoutItemMap*>(layout.itemById(QStringLiteral("sketch")));
  REQUIRE(map != nullptr);
  CHECK(map->rect().width() > 300);
  // A finite extent of its own (it was NaN: the map stayed grey, and Set to Map Canvas Extent did
  // nothing) in the frame's proportions, and one that follows the strokes once a run names them.
  const QgsRectangle extent = map->extent();
  CHECK((std::isfinite(extent.width()) && extent.width() > 0));
  CHECK(extent.width() / extent.height() == Approx(map->rect().width() / map->rect().height()));
  CHECK(map->dataDefinedProperties().count() >= 4);  // its four edges
  // A key of the two stroke classes, not a legend listing the hillshade's ramp.
  for (QGraphicsItem* item : layout.items())
    CHECK(dynamic_cast<QgsLayoutItemLegend*>(item) == nullptr);
  for (const char* id : {"key_label_factual", "key_label_formulated", "note", "credits", "north"})
    CHECK(layout.itemById(QString::fromLatin1(id)) != nullptr);
  // (Debian's qgslayoutitemscalebar.h includes a header it does not ship: the type will do.)
  const QgsLayoutItem* scale = layout.itemById(QStringLiteral("scale"));
  REQUIRE(scale != nullptr);
  CHECK(scale->type() == QgsLayoutItemRegistry::LayoutScaleBar);
}
