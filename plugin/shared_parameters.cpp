#include "plugin/shared_parameters.h"

#include <qgsprocessingfeedback.h>

#include <cmath>

#include "core/method/choice_names.h"
#include "plugin/choice_parameter.h"
#include "plugin/qgis_compat.h"

namespace tsk::plugin {

QgsProcessingParameterNumber* SharedParameters::number(const QString& key, const QString& label,
                                                       double value, double min, double max) {
  auto* parameter =
      new QgsProcessingParameterNumber(key, label, kDoubleNumber, value, false, min, max);
  // The widget's six decimals by default would show 90 as 90.000000; enough to reach the minimum.
  const int decimals = min > 0 && min < 0.01 ? 3 : 2;
  parameter->setMetadata(
      {{QStringLiteral("widget_wrapper"), QVariantMap{{QStringLiteral("decimals"), decimals}}}});
  return parameter;
}

std::vector<HelpedParameter> SharedParameters::view(bool exaggeration) {
  const ViewParams defaults;
  std::vector<HelpedParameter> view;
  view.push_back(HelpedParameter{
      number(QStringLiteral("AZIMUTH"), tr("View azimuth (degrees)"), defaults.azimuth_deg, 0, 360),
      tr("Compass bearing the viewer faces, clockwise from grid north: 0 (from the "
         "south), 90 (from the west, the default), 180 (from the north), 270 (from the "
         "east). These four are exact; any other azimuth resamples the DEM bilinearly "
         "onto a grid aligned with the line of sight, and the strokes are mapped back "
         "exactly into the DEM's CRS.")});
  if (!exaggeration) return view;
  view.push_back(
      {number(QStringLiteral("VE"), tr("Vertical exaggeration"), defaults.ve, 0.01, 1000),
       tr("Factor applied to heights before occlusion is computed.")});
  view.push_back({number(QStringLiteral("BASE_SLOPE"), tr("Base slope (%)"),
                         defaults.base_slope_pct, 0.01, 10000),
                  tr("Slope added along the line of sight, in percent: the view elevation angle is "
                     "atan(base slope) above the exaggerated terrain (40 % = 21.8 degrees).")});
  return view;
}

std::vector<HelpedParameter> SharedParameters::dem() {
  return {{new QgsProcessingParameterRasterLayer(QStringLiteral("INPUT"), tr("Elevation (DEM)")),
           tr("Digital elevation model with heights in metres, in a projected CRS in metres.")},
          // Optional, so that qgis_process and models need not give it: QGIS 3.22 asks for a band
          // parameter's value even when it has a default.
          {new QgsProcessingParameterBand(QStringLiteral("BAND"), tr("Band"), 1,
                                          QStringLiteral("INPUT"), true),
           tr("The band holding the heights (the first when none is chosen).")}};
}

std::vector<HelpedParameter> SharedParameters::filter() {
  const FilterParams defaults;
  std::vector<HelpedParameter> filter;
  filter.push_back(
      {choiceParameter(
           QStringLiteral("FILTER"), tr("Slope filter"), kFilterModeNames,
           [](FilterMode mode) {
             return mode == FilterMode::adaptive ? tr("Adapted to the DEM")
                                                 : tr("Fixed (the thesis's cut-offs)");
           },
           FilterMode::adaptive),
       tr("Adapted to the DEM (the default): the cut-offs below are scaled by the DEM's "
          "median slope over 24 %, that of the terrain the thesis tuned them on at 75 m "
          "cells (from 1/16 to 4 times), so that coarse, fine, flat and steep DEMs all "
          "give a balanced sketch; height steps within half the DEM's height unit count "
          "as flat, so the sketch holds still as the view turns. Fixed: the cut-offs as "
          "given, the thesis's filter.")});
  filter.push_back({choiceParameter(
                        QStringLiteral("ADAPT"), tr("Adapt the filter to"), kAdaptivityNames,
                        [](Adaptivity adapt) {
                          return adapt == Adaptivity::whole ? tr("The whole DEM")
                                                            : tr("Each neighbourhood");
                        },
                        Adaptivity::whole),
                    tr("With the adapted filter: one scale for the whole DEM, or a scale for each "
                       "neighbourhood, so that a plain beside mountains keeps its subtle breaks of "
                       "slope (this reads the DEM once more)."),
                    true});
  auto* window =
      new QgsProcessingParameterNumber(QStringLiteral("ADAPT_WINDOW"), tr("Neighbourhood (cells)"),
                                       kIntegerNumber, AdaptiveParams().window, false, 8, 100000);
  filter.push_back(
      {window,
       tr("With a scale for each neighbourhood: the side of a neighbourhood, in DEM "
          "cells. Scales are blended between neighbourhoods, so the filter has no seams."),
       true});
  filter.push_back({number(QStringLiteral("ROW_CUT"), tr("Row slope cut-off (%)"),
                           defaults.row_cut_pct, 0.01, 10000),
                    tr("Slope filter: row (across the view) slope below which weak candidates are "
                       "removed; 20 % is Macgregor's critical slope.")});
  filter.push_back(
      {number(QStringLiteral("COL_CUT"), tr("Column slope cut-off (%)"), defaults.col_cut_pct, 0.01,
              10000),
       tr("Slope filter: column (along the view) slope below which weak candidates are "
          "removed.")});
  filter.push_back(
      {number(QStringLiteral("CTRL_COL"), tr("Control point column slope (%)"),
              defaults.ctrl_col_pct, 0.001, 10000),
       tr("Slope filter: column slope of the control point joining the two cut-offs, on "
          "the perpendicular through the origin. Smaller values keep more diagonal "
          "features; it must be below the column cut-off.")});
  filter.push_back({new QgsProcessingParameterBoolean(
                        QStringLiteral("DIAGONALS"), tr("Allow for diagonals"), defaults.diagonals),
                    tr("If checked the removed region is the polygon through the control point; if "
                       "not, the whole rectangle below both cut-offs is removed.")});
  return filter;
}

HelpedParameter SharedParameters::strokeMode(const QString& help) {
  return {choiceParameter(
              QStringLiteral("STROKES"), tr("Strokes"), kStrokeModeNames,
              [](StrokeMode mode) {
                return mode == StrokeMode::drawn ? tr("Drawn (joined, smoothed, tapered)")
                                                 : tr("Exact (the thesis's, a point per cell)");
              },
              StrokeMode::drawn),
          help, true};
}

StrokeMode SharedParameters::readStrokeMode(const QgsProcessingAlgorithm& algorithm,
                                            const QVariantMap& parameters,
                                            QgsProcessingContext& context) {
  return parameterAsChoice(algorithm, parameters, QStringLiteral("STROKES"), context,
                           kStrokeModeNames);
}

HelpedParameter SharedParameters::geometry(Geometry defaultValue) {
  return {choiceParameter(
              QStringLiteral("GEOMETRY"), tr("Geometry"), kGeometryNames,
              [](Geometry g) {
                return g == Geometry::map ? tr("Map (cell centres)")
                                          : tr("Plan oblique (the sketch)");
              },
              defaultValue),
          tr("Map: strokes at the cell centres in the DEM's CRS. Plan oblique: each point moved "
             "along the view azimuth by (exaggeration / base slope) x (height - lowest height), so "
             "the strokes draw the oblique sketch in the same CRS.")};
}

Geometry SharedParameters::readGeometry(const QgsProcessingAlgorithm& algorithm,
                                        const QVariantMap& parameters,
                                        QgsProcessingContext& context) {
  return parameterAsChoice(algorithm, parameters, QStringLiteral("GEOMETRY"), context,
                           kGeometryNames);
}

ViewParams SharedParameters::readView(const QgsProcessingAlgorithm& algorithm,
                                      const QVariantMap& parameters,
                                      QgsProcessingContext& context) {
  const auto value = [&](const char* key) {
    return QgsProcessingParameters::parameterAsDouble(
        algorithm.parameterDefinition(QString::fromLatin1(key)), parameters, context);
  };
  ViewParams view;
  view.azimuth_deg = value("AZIMUTH");
  if (algorithm.parameterDefinition(QStringLiteral("VE"))) {
    view.ve = value("VE");
    view.base_slope_pct = value("BASE_SLOPE");
  }
  return view;
}

void SharedParameters::readFilter(const QgsProcessingAlgorithm& algorithm,
                                  const QVariantMap& parameters, QgsProcessingContext& context,
                                  SilhouetteParams& params) {
  const auto definition = [&](const char* key) {
    return algorithm.parameterDefinition(QString::fromLatin1(key));
  };
  const auto value = [&](const char* key) {
    return QgsProcessingParameters::parameterAsDouble(definition(key), parameters, context);
  };
  AdaptiveParams& adaptive = params.adaptive;
  adaptive.mode =
      parameterAsChoice(algorithm, parameters, QStringLiteral("FILTER"), context, kFilterModeNames);
  adaptive.adapt =
      parameterAsChoice(algorithm, parameters, QStringLiteral("ADAPT"), context, kAdaptivityNames);
  adaptive.window =
      QgsProcessingParameters::parameterAsInt(definition("ADAPT_WINDOW"), parameters, context);
  FilterParams& filter = params.filter;
  filter.row_cut_pct = value("ROW_CUT");
  filter.col_cut_pct = value("COL_CUT");
  filter.ctrl_col_pct = value("CTRL_COL");
  filter.diagonals =
      QgsProcessingParameters::parameterAsBool(definition("DIAGONALS"), parameters, context);
}

void SharedParameters::logFilter(const FilterReport& r, QgsProcessingFeedback* feedback) {
  if (!feedback || r.choice.mode == FilterMode::fixed) return;
  if (!std::isfinite(r.median_slope_pct)) {
    feedback->pushWarning(tr("No cell of the DEM slopes (it is flat, or too few of its cells are "
                             "valid): the slope filter's cut-offs are scaled by the least, %L1: "
                             "row %L2 %, column %L3 %, control point %L4 %.")
                              .arg(r.scale, 0, 'g', 3)
                              .arg(r.cutoffs.row_cut_pct, 0, 'g', 3)
                              .arg(r.cutoffs.col_cut_pct, 0, 'g', 3)
                              .arg(r.cutoffs.ctrl_col_pct, 0, 'g', 3));
    return;
  }
  feedback->pushInfo(tr("Slope filter adapted to the DEM: its median slope is %L1 % against %L2 % "
                        "on the thesis's terrain, so the cut-offs are scaled by %L3: row %L4 %, "
                        "column %L5 %, control point %L6 %.")
                         .arg(r.median_slope_pct, 0, 'g', 3)
                         .arg(kReferenceSlopePct, 0, 'g', 3)
                         .arg(r.scale, 0, 'g', 3)
                         .arg(r.cutoffs.row_cut_pct, 0, 'g', 3)
                         .arg(r.cutoffs.col_cut_pct, 0, 'g', 3)
                         .arg(r.cutoffs.ctrl_col_pct, 0, 'g', 3));
  if (r.choice.adapt == Adaptivity::local) {
    feedback->pushInfo(tr("Each neighbourhood of %L1 cells scales them from %L2 to %L3 times the "
                          "thesis's.")
                           .arg(r.choice.window)
                           .arg(r.local_lowest, 0, 'g', 3)
                           .arg(r.local_highest, 0, 'g', 3));
  }
}

}  // namespace tsk::plugin
