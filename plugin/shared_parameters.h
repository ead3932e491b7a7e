// The parameters several algorithms share (the DEM, the view, the slope filter, the stroke mode,
// the geometry): each definition with its help, and reading it back. An algorithm composes those
// it needs.
#pragma once

#include <qgsprocessingalgorithm.h>
#include <qgsprocessingparameters.h>

#include <QCoreApplication>
#include <vector>

#include "core/method/adaptive_filter.h"
#include "core/method/params.h"

class QgsProcessingFeedback;

namespace tsk::plugin {

// A parameter's definition with its help text, advanced or not, for the algorithm to add.
struct HelpedParameter {
  QgsProcessingParameterDefinition* definition;
  QString help;
  bool advanced = false;
};

class SharedParameters {
  Q_DECLARE_TR_FUNCTIONS(SharedParameters)

 public:
  // A decimal number parameter from `min` to `max`, its widget showing a few decimals.
  static QgsProcessingParameterNumber* number(const QString& key, const QString& label,
                                              double value, double min, double max);
  // INPUT and BAND.
  static std::vector<HelpedParameter> dem();
  // AZIMUTH; with `exaggeration` also VE and BASE_SLOPE.
  static std::vector<HelpedParameter> view(bool exaggeration);
  // FILTER, ADAPT, ADAPT_WINDOW, ROW_CUT, COL_CUT, CTRL_COL, DIAGONALS.
  static std::vector<HelpedParameter> filter();
  // STROKES, advanced: drawn (the default) or exact strokes, explained by `help`.
  static HelpedParameter strokeMode(const QString& help);
  // GEOMETRY: map or plan oblique, `defaultValue` chosen.
  static HelpedParameter geometry(Geometry defaultValue);

  static ViewParams readView(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                             QgsProcessingContext& context);
  // The filter's parameters into `params`: its cut-offs and whether they adapt to the DEM.
  static void readFilter(const QgsProcessingAlgorithm& algorithm, const QVariantMap& parameters,
                         QgsProcessingContext& context, SilhouetteParams& params);
  static StrokeMode readStrokeMode(const QgsProcessingAlgorithm& algorithm,
                                   const QVariantMap& parameters, QgsProcessingContext& context);
  static Geometry readGeometry(const QgsProcessingAlgorithm& algorithm,
                               const QVariantMap& parameters, QgsProcessingContext& context);
  // Logs which cut-offs an adaptive filter chose, and why.
  static void logFilter(const FilterReport& report, QgsProcessingFeedback* feedback);
};

}  // namespace tsk::plugin
