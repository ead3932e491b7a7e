// The drawn styles' taper in QGIS: a line symbol layer that fills each stroke's outline with the
// width its every vertex carries (its M value, the drawn strokes' weight), as the vector art does.
// QGIS's own line layers draw one width per feature, and buffer_by_m takes minutes for a real
// DEM's strokes.
#pragma once

#include <qgssymbollayer.h>

#include <QColor>
#include <vector>

#include "core/method/strokes.h"

namespace tsk::plugin {

class TaperedLineSymbolLayer : public QgsLineSymbolLayer {
 public:
  // The name a style file gives the layer's class.
  static const QString kLayerType;

  explicit TaperedLineSymbolLayer(const QColor& color = QColor(17, 17, 17), double widthMm = 0.7);
  static QgsSymbolLayer* create(const QVariantMap& properties);

  QString layerType() const override { return kLayerType; }
  void startRender(QgsSymbolRenderContext&) override {}
  void stopRender(QgsSymbolRenderContext&) override {}
  QgsSymbolLayer* clone() const override;
  QVariantMap properties() const override;
  void renderPolyline(const QPolygonF& points, QgsSymbolRenderContext& context) override;
  double estimateMaxBleed(const QgsRenderContext& context) const override;

 private:
  // The rendered part of the feature as painter points with their weights, when it is a line
  // with M values; false otherwise (a legend swatch, a polygon's outline, a line without M).
  static bool weightedVertices(const QgsSymbolRenderContext& context,
                               std::vector<StrokePoint>& points, std::vector<double>& weights);
};

// Registers the layer type, and the expression function terrain_sketch_draws_taper() that the
// styles' stepped stand-in layers read to switch themselves off while the plugin draws the taper.
// Without the plugin QGIS drops the unknown layer, the function is unknown, and the stand-ins
// draw. Safe to call again.
void registerTaperedLine();
void unregisterTaperedLine();

}  // namespace tsk::plugin
