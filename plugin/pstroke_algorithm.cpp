#include "plugin/pstroke_algorithm.h"

#include <qgsprocessingfeedback.h>

#include "core/base/errors.h"
#include "core/method/silhouettes.h"
#include "plugin/layer_style.h"
#include "plugin/line_output.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"
#include "plugin/run_notes.h"
#include "plugin/stroke_features.h"

namespace tsk::plugin {

QString PStrokeAlgorithm::name() const {
  return QStringLiteral("pstrokes");
}
QString PStrokeAlgorithm::displayName() const {
  return tr("P-stroke sketch");
}

QString PStrokeAlgorithm::shortHelpString() const {
  return tr(
      "Short strokes drawn across the line of sight where the terrain bends (Visvalingam "
      "and Dowson 1998). Every profile along the view (column) and across it (row) is "
      "scored with Visvalingam's effective-area line generalisation; a visible cell whose "
      "convex or concave score reaches its class's tolerance seeds a stroke along the "
      "cross-section. Tolerances are effective areas in square metres of the triangles "
      "formed by distance (m) and unexaggerated height (m) along the profiles; the "
      "defaults are the thesis's sparse sketch of a 50 m DEM. Combined with the "
      "silhouettes: no P-stroke is seeded in an f-set cell and none is extended into one.");
}

PStrokeAlgorithm* PStrokeAlgorithm::createInstance() const {
  return new PStrokeAlgorithm();
}

void PStrokeAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(SharedParameters::filter());
  const PStrokeParams defaults;
  auto area = [this](const QString& key, const QString& label, double value, const QString& help) {
    addWithHelp(SharedParameters::number(key, label, value, 0.001, 1e12), help);
  };
  area(QStringLiteral("CONVEX_COLUMN"), tr("Convex column tolerance (m²)"),
       defaults.convex_column_m2, tr("Effective area a convex bend along the view must reach."));
  area(QStringLiteral("CONCAVE_COLUMN"), tr("Concave column tolerance (m²)"),
       defaults.concave_column_m2, tr("Effective area a concave bend along the view must reach."));
  area(QStringLiteral("CONVEX_ROW"), tr("Convex row tolerance (m²)"), defaults.convex_row_m2,
       tr("Effective area a convex bend across the view must reach."));
  area(QStringLiteral("CONCAVE_ROW"), tr("Concave row tolerance (m²)"), defaults.concave_row_m2,
       tr("Effective area a concave bend across the view must reach."));
  addWithHelp(new QgsProcessingParameterNumber(QStringLiteral("HALF_LENGTH"),
                                               tr("Stroke half length (cells)"), kIntegerNumber,
                                               defaults.half_length, false, 1, 100),
              tr("Cells drawn on each side of a seed along the cross-section."));
  addWithHelp(SharedParameters::geometry(Geometry::oblique));
  addWithHelp(
      new QgsProcessingParameterFeatureSink(QStringLiteral("OUTPUT"), tr("P-strokes"), kLineLayer),
      tr("P-strokes as lines with their class and score."));
}

double PStrokeAlgorithm::readParameters(const QVariantMap& parameters,
                                        QgsProcessingContext& context) {
  mParams.view = SharedParameters::readView(*this, parameters, context);
  SharedParameters::readFilter(*this, parameters, context, mParams);
  mParams.validate();
  mPStrokes.convex_column_m2 =
      parameterAsDouble(parameters, QStringLiteral("CONVEX_COLUMN"), context);
  mPStrokes.concave_column_m2 =
      parameterAsDouble(parameters, QStringLiteral("CONCAVE_COLUMN"), context);
  mPStrokes.convex_row_m2 = parameterAsDouble(parameters, QStringLiteral("CONVEX_ROW"), context);
  mPStrokes.concave_row_m2 = parameterAsDouble(parameters, QStringLiteral("CONCAVE_ROW"), context);
  mPStrokes.half_length = parameterAsInt(parameters, QStringLiteral("HALF_LENGTH"), context);
  mPStrokes.validate();
  mParams.geometry = SharedParameters::readGeometry(*this, parameters, context);
  return mParams.view.azimuth_deg;
}

QVariantMap PStrokeAlgorithm::writeOutputs(const QVariantMap& parameters,
                                           QgsProcessingContext& context,
                                           QgsProcessingFeedback* feedback) {
  const RasterGrid& raster = readRaster(feedback, 25);
  const std::vector<PStroke> strokes = withCoreErrors([&] {
    PStrokeRun run =
        sketch_pstrokes(raster.held(), mParams, mPStrokes, progressBetween(feedback, 25, 40));
    SharedParameters::logFilter(run.filter, feedback);
    mNote = productNote(demName(), tr("P-strokes"), mParams.view, &run.filter);
    return std::move(run.strokes);
  });
  QgsFields fields;
  fields.append(makeField(QStringLiteral("class"), FieldKind::Text));
  fields.append(makeField(QStringLiteral("score_m2"), FieldKind::Real));
  LineOutput output(*this, parameters, QStringLiteral("OUTPUT"), context, fields, raster.crs(),
                    feedback);
  for (const PStroke& s : strokes) {
    QgsFeature feature(fields);
    QgsAttributes attributes;
    attributes << QString::fromLatin1(pstroke_class_name(s.cls)) << s.score_m2;
    feature.setAttributes(attributes);
    feature.setGeometry(lineGeometry(s.points));
    addWithProgress(output, feature, feedback, strokes.size(), 50);
  }
  output.finish(mNote.abstract);
  mOutput = output.destination();
  releaseRaster();
  return {{QStringLiteral("OUTPUT"), mOutput}};
}

QVariantMap PStrokeAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                   QgsProcessingFeedback*) {
  styleOnCompletion(context, mOutput, QStringLiteral("pstrokes"), RampRange::style, mNote);
  return {};
}

}  // namespace tsk::plugin
