#include "plugin/tapered_line.h"

#include <qgsapplication.h>
#include <qgsexception.h>
#include <qgsexpression.h>
#include <qgsexpressionfunction.h>
#include <qgsgeometrycollection.h>
#include <qgslinestring.h>
#include <qgsrendercontext.h>
#include <qgssymbollayerregistry.h>
#include <qgssymbollayerutils.h>
#include <qgssymbolrendercontext.h>
#include <qgsunittypes.h>

#include <QCoreApplication>
#include <QPainter>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/drawn/stroke_outline.h"
#include "plugin/qgis_compat.h"

namespace tsk::plugin {

const QString TaperedLineSymbolLayer::kLayerType = QStringLiteral("TerrainSketchTaperedLine");

namespace {

const QString kDrawsTaper = QStringLiteral("terrain_sketch_draws_taper");

// True wherever the plugin is loaded: the drawn styles' stepped stand-ins switch themselves off.
class DrawsTaperFunction : public QgsExpressionFunction {
 public:
  DrawsTaperFunction()
      : QgsExpressionFunction(kDrawsTaper, 0, QStringLiteral("General"),
                              QCoreApplication::translate(
                                  "TaperedLine",
                                  "<h3>terrain_sketch_draws_taper()</h3><div>True while the "
                                  "Terrain Sketch plugin is loaded and draws the width of every "
                                  "vertex of drawn strokes. Its styles' stepped lines are "
                                  "enabled only where it is unknown.</div>")) {}
  QVariant func(const QVariantList&, const QgsExpressionContext*, QgsExpression*,
                const QgsExpressionNodeFunction*) override {
    return true;
  }
};

// A vertex's weight from its M value: within [0, 1], and whole where it is not a number.
double weightOf(double m) {
  return std::isfinite(m) ? std::clamp(m, 0.0, 1.0) : 1.0;
}

}  // namespace

TaperedLineSymbolLayer::TaperedLineSymbolLayer(const QColor& color, double widthMm) {
  mColor = color;
  mWidth = widthMm;
}

QgsSymbolLayer* TaperedLineSymbolLayer::create(const QVariantMap& properties) {
  auto* layer = new TaperedLineSymbolLayer(
      QgsSymbolLayerUtils::decodeColor(
          properties.value(QStringLiteral("line_color"), QStringLiteral("17,17,17")).toString()),
      properties.value(QStringLiteral("line_width"), 0.7).toDouble());
  if (properties.contains(QStringLiteral("line_width_unit")))
    layer->setWidthUnit(QgsUnitTypes::decodeRenderUnit(
        properties.value(QStringLiteral("line_width_unit")).toString()));
  if (properties.contains(QStringLiteral("width_map_unit_scale")))
    layer->setWidthMapUnitScale(QgsSymbolLayerUtils::decodeMapUnitScale(
        properties.value(QStringLiteral("width_map_unit_scale")).toString()));
  return layer;
}

QgsSymbolLayer* TaperedLineSymbolLayer::clone() const {
  auto* copy = new TaperedLineSymbolLayer(mColor, mWidth);
  copy->setWidthUnit(mWidthUnit);
  copy->setWidthMapUnitScale(mWidthMapUnitScale);
  copyDataDefinedProperties(copy);
  copyPaintEffect(copy);
  return copy;
}

QVariantMap TaperedLineSymbolLayer::properties() const {
  QVariantMap map;
  map.insert(QStringLiteral("line_color"), QgsSymbolLayerUtils::encodeColor(mColor));
  map.insert(QStringLiteral("line_width"), QString::number(mWidth));
  map.insert(QStringLiteral("line_width_unit"), QgsUnitTypes::encodeUnit(mWidthUnit));
  map.insert(QStringLiteral("width_map_unit_scale"),
             QgsSymbolLayerUtils::encodeMapUnitScale(mWidthMapUnitScale));
  return map;
}

double TaperedLineSymbolLayer::estimateMaxBleed(const QgsRenderContext& context) const {
  return context.convertToPainterUnits(mWidth, mWidthUnit, mWidthMapUnitScale) / 2;
}

bool TaperedLineSymbolLayer::weightedVertices(const QgsSymbolRenderContext& context,
                                              std::vector<StrokePoint>& points,
                                              std::vector<double>& weights) {
  const QgsFeature* feature = context.feature();
  if (!feature || !feature->hasGeometry()) return false;
  const QgsAbstractGeometry* geometry = feature->geometry().constGet();
  if (const auto* parts = qgsgeometry_cast<const QgsGeometryCollection*>(geometry))
    geometry = parts->geometryN(context.geometryPartNum() - 1);
  const auto* line = qgsgeometry_cast<const QgsLineString*>(geometry);
  if (!line || !line->isMeasure()) return false;
  const QgsRenderContext& render = context.renderContext();
  const QgsCoordinateTransform transform = render.coordinateTransform();
  const int n = line->numPoints();
  points.resize(static_cast<std::size_t>(n));
  weights.resize(static_cast<std::size_t>(n));
  try {
    for (int k = 0; k < n; ++k) {
      double x = line->xAt(k), y = line->yAt(k), z = 0.0;
      if (transform.isValid()) transform.transformInPlace(x, y, z);
      render.mapToPixel().transformInPlace(x, y);
      points[static_cast<std::size_t>(k)] = {x, y};
      weights[static_cast<std::size_t>(k)] = weightOf(line->mAt(k));
    }
  } catch (const QgsCsException&) {
    return false;  // drawn as QGIS placed it, at full width
  }
  return true;
}

void TaperedLineSymbolLayer::renderPolyline(const QPolygonF& points,
                                            QgsSymbolRenderContext& context) {
  QPainter* painter = context.renderContext().painter();
  if (!painter) return;
  std::vector<StrokePoint> line;
  std::vector<double> widths;  // each vertex's weight, then its width
  if (!weightedVertices(context, line, widths)) {
    line.clear();
    for (const QPointF& p : points) line.push_back({p.x(), p.y()});
    widths.assign(line.size(), 1.0);
  }
  QgsExpressionContext& expressions = context.renderContext().expressionContext();
  double width = mWidth;
  if (mDataDefinedProperties.isActive(kStrokeWidthProperty)) {
    context.setOriginalValueVariable(mWidth);
    width = mDataDefinedProperties.valueAsDouble(kStrokeWidthProperty, expressions, mWidth);
  }
  const double fullWidth =
      context.renderContext().convertToPainterUnits(width, mWidthUnit, mWidthMapUnitScale);
  QColor color = mColor;
  if (context.selected()) {
    color = context.renderContext().selectionColor();
  } else if (mDataDefinedProperties.isActive(kStrokeColorProperty)) {
    context.setOriginalValueVariable(QgsSymbolLayerUtils::encodeColor(mColor));
    color = mDataDefinedProperties.valueAsColor(kStrokeColorProperty, expressions, mColor);
  }
  color.setAlphaF(color.alphaF() * context.opacity());

  for (double& w : widths) w *= fullWidth;
  const std::vector<StrokePoint> outline = tapered_outline(line, widths);
  if (outline.empty()) return;
  QPolygonF polygon;
  polygon.reserve(static_cast<int>(outline.size()));
  for (const StrokePoint& p : outline) polygon << QPointF(p.x, p.y);
  painter->setPen(Qt::NoPen);
  painter->setBrush(color);
  painter->drawPolygon(polygon, Qt::WindingFill);
}

void registerTaperedLine() {
  QgsSymbolLayerRegistry* registry = QgsApplication::symbolLayerRegistry();
  if (!registry->symbolLayerMetadata(TaperedLineSymbolLayer::kLayerType))
    registry->addSymbolLayerType(new QgsSymbolLayerMetadata(
        TaperedLineSymbolLayer::kLayerType,
        QCoreApplication::translate("TaperedLine", "Tapered line (Terrain Sketch)"),
        Qgis::SymbolType::Line, &TaperedLineSymbolLayer::create));
  if (!QgsExpression::isFunctionName(kDrawsTaper))
    QgsExpression::registerFunction(new DrawsTaperFunction, true);
}

void unregisterTaperedLine() {
  QgsSymbolLayerRegistry* registry = QgsApplication::symbolLayerRegistry();
  if (QgsSymbolLayerAbstractMetadata* metadata =
          registry->symbolLayerMetadata(TaperedLineSymbolLayer::kLayerType))
    registry->removeSymbolLayerType(metadata);
  QgsExpression::unregisterFunction(kDrawsTaper);
}

}  // namespace tsk::plugin
