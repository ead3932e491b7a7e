#include "plugin/row_slope_algorithm.h"

#include <qgsprocessingfeedback.h>

#include "core/applications/diagnostics.h"
#include "plugin/layer_style.h"
#include "plugin/raster_grid.h"
#include "plugin/raster_output.h"
#include "plugin/run_notes.h"

namespace tsk::plugin {

QString RowSlopeAlgorithm::name() const {
  return QStringLiteral("rowslope");
}
QString RowSlopeAlgorithm::displayName() const {
  return tr("Row slope map");
}

QString RowSlopeAlgorithm::shortHelpString() const {
  return tr(
      "The magnitude of the slope across the line of sight, in percent, on the DEM's grid "
      "(central differences across the view). Styled light where the terrain is flat "
      "across the view and dark where it is steep, the backdrop the thesis uses under its "
      "silhouettes. Only the azimuth matters.");
}

RowSlopeAlgorithm* RowSlopeAlgorithm::createInstance() const {
  return new RowSlopeAlgorithm();
}

void RowSlopeAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(false));
  addWithHelp(
      new QgsProcessingParameterRasterDestination(QStringLiteral("OUTPUT"), tr("Row slope")),
      tr("Float32 raster of |row slope| in percent."));
}

double RowSlopeAlgorithm::readParameters(const QVariantMap& parameters,
                                         QgsProcessingContext& context) {
  mView = SharedParameters::readView(*this, parameters, context);
  mView.validate();
  return mView.azimuth_deg;
}

QVariantMap RowSlopeAlgorithm::writeOutputs(const QVariantMap& parameters,
                                            QgsProcessingContext& context,
                                            QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 70);
  mOutput = parameterAsOutputLayer(parameters, QStringLiteral("OUTPUT"), context);
  mNote = productNote(demName(), tr("Row slope"), mView);
  writeFloatRaster(mOutput, {row_slope_map(raster.oriented(), raster.frame())},
                   raster.geotransform(), raster.crs(), mNote.abstract);
  releaseRaster();
  return {{QStringLiteral("OUTPUT"), mOutput}};
}

QVariantMap RowSlopeAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                    QgsProcessingFeedback*) {
  styleOnCompletion(context, mOutput, QStringLiteral("row_slope"), RampRange::data, mNote);
  return {};
}

}  // namespace tsk::plugin
