#include "plugin/profile_plot_algorithm.h"

#include <qgsprocessingfeedback.h>

#include "core/base/errors.h"
#include "plugin/layer_style.h"
#include "plugin/line_output.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"
#include "plugin/run_notes.h"
#include "plugin/stroke_features.h"

namespace tsk::plugin {

QString ProfilePlotAlgorithm::name() const {
  return QStringLiteral("profileplot");
}
QString ProfilePlotAlgorithm::displayName() const {
  return tr("Profile plot (ridgelines)");
}

QString ProfilePlotAlgorithm::shortHelpString() const {
  return tr(
      "Draws every n-th cross-section across the line of sight as it appears in the "
      "oblique view: in plan-oblique geometry (each point moved along the view azimuth by "
      "exaggeration / base slope x (height - lowest height)), with the parts hidden behind "
      "nearer terrain removed. The classic ridgeline sketch; it overlays the plan-oblique "
      "silhouettes exactly. Each line carries its cross-section number and its distance "
      "from the front of the view.");
}

ProfilePlotAlgorithm* ProfilePlotAlgorithm::createInstance() const {
  return new ProfilePlotAlgorithm();
}

void ProfilePlotAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(
      new QgsProcessingParameterNumber(QStringLiteral("EVERY"), tr("Every n-th cross-section"),
                                       kIntegerNumber, 10, false, 1, 100000),
      tr("Distance between drawn cross-sections, in cells along the line of sight."));
  addWithHelp(new QgsProcessingParameterFeatureSink(QStringLiteral("OUTPUT"), tr("Profile plot"),
                                                    kLineLayer),
              tr("Visible pieces of the cross-sections as lines."));
}

double ProfilePlotAlgorithm::readParameters(const QVariantMap& parameters,
                                            QgsProcessingContext& context) {
  mView = SharedParameters::readView(*this, parameters, context);
  mView.validate();
  mEvery = parameterAsInt(parameters, QStringLiteral("EVERY"), context);
  if (mEvery < 1) throw Error("the cross-section step must be at least 1");
  return mView.azimuth_deg;
}

QVariantMap ProfilePlotAlgorithm::writeOutputs(const QVariantMap& parameters,
                                               QgsProcessingContext& context,
                                               QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 50);
  const std::vector<ProfileLine> lines = withCoreErrors(
      [&] { return plot_profiles(raster.held(), mView, static_cast<std::size_t>(mEvery), 0); });
  QgsFields fields;
  fields.append(makeField(QStringLiteral("section"), FieldKind::Integer));
  fields.append(makeField(QStringLiteral("distance"), FieldKind::Real));
  LineOutput output(*this, parameters, QStringLiteral("OUTPUT"), context, fields, raster.crs(),
                    feedback);
  for (const ProfileLine& line : lines) {
    QgsFeature feature(fields);
    // Not a braced list: QgsAttributes{n, value} is n copies of the value (QVector's constructor).
    QgsAttributes attributes;
    attributes << static_cast<int>(line.cross_section) << line.distance;
    feature.setAttributes(attributes);
    feature.setGeometry(lineGeometry(line.points));
    addWithProgress(output, feature, feedback, lines.size(), 50);
  }
  mNote = productNote(demName(), tr("Profile lines"), mView);
  output.finish(mNote.abstract);
  mOutput = output.destination();
  releaseRaster();
  return {{QStringLiteral("OUTPUT"), mOutput}};
}

QVariantMap ProfilePlotAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                       QgsProcessingFeedback*) {
  styleOnCompletion(context, mOutput, QStringLiteral("profiles"), RampRange::style, mNote);
  return {};
}

}  // namespace tsk::plugin
