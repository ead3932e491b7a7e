#include "plugin/layer_style.h"

#include <qgsexpressioncontextutils.h>
#include <qgslayermetadata.h>
#include <qgsmaplayer.h>
#include <qgsprocessingfeedback.h>
#include <qgsproject.h>
#include <qgsrasterlayer.h>
#include <qgsrenderer.h>
#include <qgsvectorlayer.h>

#include <QCoreApplication>
#include <QFileInfo>

#include "plugin/plugin_paths.h"
#include "plugin/qgis_compat.h"

namespace tsk::plugin {
namespace {

class QmlStyler : public QgsProcessingLayerPostProcessorInterface {
  Q_DECLARE_TR_FUNCTIONS(QmlStyler)

 public:
  QmlStyler(const QString& qmlPath, RampRange range, const RunNote& note)
      : mQmlPath(qmlPath), mRange(range), mNote(note) {}

  void postProcessLayer(QgsMapLayer* layer, QgsProcessingContext& context,
                        QgsProcessingFeedback* feedback) override {
    if (!layer) return;
    record(*layer, context.project());
    bool ok = false;
    const QString message = layer->loadNamedStyle(mQmlPath, ok);
    if (!ok && feedback) {
      feedback->reportError(tr("Could not apply style %1: %2").arg(mQmlPath, message), false);
    }
    if (!ok) return;
    auto* vector = qobject_cast<QgsVectorLayer*>(layer);
    if (vector && vector->renderer() && mNote.referenceScale > 0)
      vector->renderer()->setReferenceScale(mNote.referenceScale);
    auto* raster = qobject_cast<QgsRasterLayer*>(layer);
    if (raster && mRange == RampRange::data) {
      raster->setContrastEnhancement(QgsContrastEnhancement::StretchToMinimumMaximum,
                                     kCumulativeCut, QgsRectangle(), 250000);
    }
    layer->triggerRepaint();
  }

 private:
  void record(QgsMapLayer& layer, QgsProject* project) const {
    if (mNote.layout && project) mNote.layout->add(*project, layer, mNote.panorama);
    if (mNote.abstract.isEmpty()) return;
    QgsLayerMetadata metadata = layer.metadata();
    if (!mNote.title.isEmpty()) metadata.setTitle(mNote.title);
    metadata.setAbstract(mNote.abstract);
    layer.setMetadata(metadata);
    if (!mNote.sketch || !project) return;
    QgsExpressionContextUtils::setProjectVariable(project, QStringLiteral("terrain_sketch_layer"),
                                                  layer.id());
    QgsExpressionContextUtils::setProjectVariable(project, QStringLiteral("terrain_sketch_note"),
                                                  mNote.abstract);
  }

  QString mQmlPath;
  RampRange mRange;
  RunNote mNote;
};

}  // namespace

void styleOnCompletion(QgsProcessingContext& context, const QString& destinationId,
                       const QString& style, RampRange range, const RunNote& note) {
  if (destinationId.isEmpty() || !context.willLoadLayerOnCompletion(destinationId)) return;
  const QString qml = stylePath(style);
  if (!QFileInfo::exists(qml)) return;
  QgsProcessingContext::LayerDetails& details =
      context.layerToLoadOnCompletionDetails(destinationId);
  if (!note.title.isEmpty()) details.name = note.title;  // the layer's name says the view
  details.setPostProcessor(new QmlStyler(qml, range, note));
}

}  // namespace tsk::plugin
