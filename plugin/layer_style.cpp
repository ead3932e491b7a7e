#include "layer_style.h"

#include <qgsmaplayer.h>
#include <qgsprocessingfeedback.h>

#include <QCoreApplication>
#include <QFileInfo>

#include "plugin_paths.h"

namespace tsk::plugin {
namespace {

class QmlStyler : public QgsProcessingLayerPostProcessorInterface {
  Q_DECLARE_TR_FUNCTIONS(QmlStyler)

 public:
  explicit QmlStyler(const QString& qmlPath) : mQmlPath(qmlPath) {}

  void postProcessLayer(QgsMapLayer* layer, QgsProcessingContext&,
                        QgsProcessingFeedback* feedback) override {
    if (!layer) return;
    bool ok = false;
    const QString message = layer->loadNamedStyle(mQmlPath, ok);
    if (!ok && feedback) {
      feedback->reportError(tr("Could not apply style %1: %2").arg(mQmlPath, message), false);
    }
    if (ok) layer->triggerRepaint();
  }

 private:
  QString mQmlPath;
};

}  // namespace

void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style) {
  if (destinationId.isEmpty() || !context.willLoadLayerOnCompletion(destinationId)) return;
  const QString qml = stylePath(style);
  if (!QFileInfo::exists(qml)) return;
  context.layerToLoadOnCompletionDetails(destinationId).setPostProcessor(new QmlStyler(qml));
}

}  // namespace tsk::plugin
