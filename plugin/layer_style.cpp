#include "plugin/layer_style.h"

#include <qgsmaplayer.h>
#include <qgsprocessingfeedback.h>
#include <qgsrasterlayer.h>

#include <QCoreApplication>
#include <QFileInfo>

#include "plugin/plugin_paths.h"
#include "plugin/qgis_compat.h"

namespace tsk::plugin {
namespace {

class QmlStyler : public QgsProcessingLayerPostProcessorInterface {
  Q_DECLARE_TR_FUNCTIONS(QmlStyler)

 public:
  QmlStyler(const QString& qmlPath, RampRange range) : mQmlPath(qmlPath), mRange(range) {}

  void postProcessLayer(QgsMapLayer* layer, QgsProcessingContext&,
                        QgsProcessingFeedback* feedback) override {
    if (!layer) return;
    bool ok = false;
    const QString message = layer->loadNamedStyle(mQmlPath, ok);
    if (!ok && feedback) {
      feedback->reportError(tr("Could not apply style %1: %2").arg(mQmlPath, message), false);
    }
    if (!ok) return;
    auto* raster = qobject_cast<QgsRasterLayer*>(layer);
    if (raster && mRange == RampRange::data) {
      raster->setContrastEnhancement(QgsContrastEnhancement::StretchToMinimumMaximum,
                                     kCumulativeCut, QgsRectangle(), 250000);
    }
    layer->triggerRepaint();
  }

 private:
  QString mQmlPath;
  RampRange mRange;
};

}  // namespace

void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style, RampRange range) {
  if (destinationId.isEmpty() || !context.willLoadLayerOnCompletion(destinationId)) return;
  const QString qml = stylePath(style);
  if (!QFileInfo::exists(qml)) return;
  context.layerToLoadOnCompletionDetails(destinationId).setPostProcessor(new QmlStyler(qml, range));
}

}  // namespace tsk::plugin
