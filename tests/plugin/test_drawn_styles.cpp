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

#include <QDomDocument>
#include <QFile>
#include <cmath>

#include "plugin_test_support.h"

using namespace tsk::plugin_test;

namespace {

// Dark pixels of a layer drawn over its extent at 1:`scale` (96 dpi), with a style from the
// plugin folder.
long long darkPixels(QgsVectorLayer& layer, const QString& style, double scale) {
  bool ok = false;
  layer.loadNamedStyle(QStringLiteral(TSK_PLUGIN_DIR "/styles/") + style, ok);
  REQUIRE(ok);
  QgsMapSettings settings;
  settings.setLayers({&layer});
  settings.setDestinationCrs(layer.crs());
  settings.setOutputDpi(96);
  settings.setOutputSize(QSize(800, 800));
  const QgsPointXY centre = layer.extent().center();
  const double half = 800 / 96.0 * 0.0254 * scale / 2;  // metres across half the picture
  settings.setExtent(
      QgsRectangle(centre.x() - half, centre.y() - half, centre.x() + half, centre.y() + half));
  settings.setBackgroundColor(Qt::white);
  QgsExpressionContext context;
  context.appendScope(QgsExpressionContextUtils::mapSettingsScope(settings));
  settings.setExpressionContext(context);
  QgsMapRendererSequentialJob job(settings);
  job.start();
  job.waitForFinished();
  const QImage image = job.renderedImage();
  long long dark = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) dark += qGray(image.pixel(x, y)) < 128;
  return dark;
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
