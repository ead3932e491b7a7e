#include "plugin/classification_algorithm.h"

#include <qgsprocessingfeedback.h>
#include <qgsprocessingoutputs.h>

#include "core/applications/diagnostics.h"
#include "core/method/silhouettes.h"
#include "plugin/layer_style.h"
#include "plugin/raster_grid.h"
#include "plugin/raster_output.h"
#include "plugin/run_notes.h"

namespace tsk::plugin {

QString ClassificationAlgorithm::name() const {
  return QStringLiteral("classification");
}

QString ClassificationAlgorithm::displayName() const {
  return tr("Silhouette stages (classification raster)");
}

QString ClassificationAlgorithm::shortHelpString() const {
  return tr(
      "Shows what the silhouette method does to every cell of the DEM, on the DEM's own "
      "grid: 1 visible, 2 hidden, 3 occluding (Factual Silhouette), 4 c-set (back-facing "
      "slope brought into view), 5 f-set (kept by the slope filter), 6 t-set (kept by "
      "thinning); 0 is nodata. Styled like the thesis's map views: occlusion red, hidden "
      "zones blue, c-set light grey, f-set dark grey. The stage statistics are in the "
      "results and the log.");
}

ClassificationAlgorithm* ClassificationAlgorithm::createInstance() const {
  return new ClassificationAlgorithm();
}

void ClassificationAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(SharedParameters::filter());
  addWithHelp(new QgsProcessingParameterRasterDestination(QStringLiteral("OUTPUT"),
                                                          tr("Silhouette stages")),
              tr("Byte raster of stage classes on the DEM's grid."));
  for (const StageFigure& f : stage_figures(StageStats{})) {
    addOutput(new QgsProcessingOutputNumber(QString::fromLatin1(f.key).toUpper(),
                                            QString::fromLatin1(f.key)));
  }
}

double ClassificationAlgorithm::readParameters(const QVariantMap& parameters,
                                               QgsProcessingContext& context) {
  mParams.view = SharedParameters::readView(*this, parameters, context);
  SharedParameters::readFilter(*this, parameters, context, mParams);
  mParams.validate();
  return mParams.view.azimuth_deg;
}

QVariantMap ClassificationAlgorithm::writeOutputs(const QVariantMap& parameters,
                                                  QgsProcessingContext& context,
                                                  QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 25);
  const SilhouetteResult result = runSilhouettes(mParams, feedback, 25, 90);
  mOutput = parameterAsOutputLayer(parameters, QStringLiteral("OUTPUT"), context);
  mNote = productNote(demName(), tr("Silhouette stages"), mParams.view, &result.filter);
  writeByteRaster(mOutput, classification_map(result.flags, raster.frame()), raster,
                  mNote.abstract);
  QVariantMap outputs{{QStringLiteral("OUTPUT"), mOutput}};
  for (const StageFigure& f : stage_figures(result.stats)) {
    outputs.insert(QString::fromLatin1(f.key).toUpper(), f.value);
    if (feedback)
      feedback->pushInfo(QStringLiteral("%1: %2").arg(QLatin1String(f.key)).arg(f.value));
  }
  releaseRaster();
  return outputs;
}

QVariantMap ClassificationAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                          QgsProcessingFeedback*) {
  styleOnCompletion(context, mOutput, QStringLiteral("classification"), RampRange::style, mNote);
  return {};
}

}  // namespace tsk::plugin
