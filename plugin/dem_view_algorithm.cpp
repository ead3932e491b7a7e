#include "plugin/dem_view_algorithm.h"

#include <qgsprocessingfeedback.h>
#include <qgsproviderregistry.h>
#include <qgsrasterlayer.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QIcon>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/base/errors.h"
#include "io/write/path_clashes.h"
#include "plugin/choice_parameter.h"
#include "plugin/line_output.h"
#include "plugin/plugin_paths.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"

namespace tsk::plugin {

DemViewAlgorithm::DemViewAlgorithm() = default;
DemViewAlgorithm::~DemViewAlgorithm() = default;

QIcon DemViewAlgorithm::icon() const {
  return QIcon(iconPath());
}
QString DemViewAlgorithm::svgIconPath() const {
  return iconPath();
}

void DemViewAlgorithm::addWithHelp(QgsProcessingParameterDefinition* parameter, const QString& help,
                                   bool advanced) {
  parameter->setHelp(help);
  if (advanced) parameter->setFlags(parameter->flags() | kAdvanced);
  addParameter(parameter);
}

QgsProcessingParameterNumber* DemViewAlgorithm::number(const QString& key, const QString& label,
                                                       double value, double min, double max) {
  auto* parameter =
      new QgsProcessingParameterNumber(key, label, kDoubleNumber, value, false, min, max);
  // The widget's six decimals by default would show 90 as 90.000000; enough to reach the minimum.
  const int decimals = min > 0 && min < 0.01 ? 3 : 2;
  parameter->setMetadata(
      {{QStringLiteral("widget_wrapper"), QVariantMap{{QStringLiteral("decimals"), decimals}}}});
  return parameter;
}

void DemViewAlgorithm::addDemAndViewParameters(bool exaggeration) {
  addDemParameters();
  const ViewParams defaults;
  addWithHelp(
      number(QStringLiteral("AZIMUTH"), tr("View azimuth (degrees)"), defaults.azimuth_deg, 0, 360),
      tr("Compass bearing the viewer faces, clockwise from grid north: 0 (from the "
         "south), 90 (from the west, the default), 180 (from the north), 270 (from the "
         "east). These four are exact; any other azimuth resamples the DEM bilinearly "
         "onto a grid aligned with the line of sight, and the strokes are mapped back "
         "exactly into the DEM's CRS."));
  if (!exaggeration) return;
  addWithHelp(number(QStringLiteral("VE"), tr("Vertical exaggeration"), defaults.ve, 0.01, 1000),
              tr("Factor applied to heights before occlusion is computed."));
  addWithHelp(number(QStringLiteral("BASE_SLOPE"), tr("Base slope (%)"), defaults.base_slope_pct,
                     0.01, 10000),
              tr("Slope added along the line of sight, in percent: the view elevation angle is "
                 "atan(base slope) above the exaggerated terrain (40 % = 21.8 degrees)."));
}

void DemViewAlgorithm::addDemParameters() {
  addWithHelp(new QgsProcessingParameterRasterLayer(QStringLiteral("INPUT"), tr("Elevation (DEM)")),
              tr("Digital elevation model with heights in metres, in a projected CRS in metres."));
  // Optional, so that qgis_process and models need not give it: QGIS 3.22 asks for a band
  // parameter's value even when it has a default.
  addWithHelp(new QgsProcessingParameterBand(QStringLiteral("BAND"), tr("Band"), 1,
                                             QStringLiteral("INPUT"), true),
              tr("The band holding the heights (the first when none is chosen)."));
}

void DemViewAlgorithm::addFilterParameters() {
  const FilterParams defaults;
  addWithHelp(choiceParameter(
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
                 "given, the thesis's filter."));
  addWithHelp(choiceParameter(
                  QStringLiteral("ADAPT"), tr("Adapt the filter to"), kAdaptivityNames,
                  [](Adaptivity adapt) {
                    return adapt == Adaptivity::whole ? tr("The whole DEM")
                                                      : tr("Each neighbourhood");
                  },
                  Adaptivity::whole),
              tr("With the adapted filter: one scale for the whole DEM, or a scale for each "
                 "neighbourhood, so that a plain beside mountains keeps its subtle breaks of "
                 "slope (this reads the DEM once more)."),
              true);
  auto* window =
      new QgsProcessingParameterNumber(QStringLiteral("ADAPT_WINDOW"), tr("Neighbourhood (cells)"),
                                       kIntegerNumber, AdaptiveParams().window, false, 8, 100000);
  addWithHelp(window,
              tr("With a scale for each neighbourhood: the side of a neighbourhood, in DEM "
                 "cells. Scales are blended between neighbourhoods, so the filter has no seams."),
              true);
  addWithHelp(number(QStringLiteral("ROW_CUT"), tr("Row slope cut-off (%)"), defaults.row_cut_pct,
                     0.01, 10000),
              tr("Slope filter: row (across the view) slope below which weak candidates are "
                 "removed; 20 % is Macgregor's critical slope."));
  addWithHelp(number(QStringLiteral("COL_CUT"), tr("Column slope cut-off (%)"),
                     defaults.col_cut_pct, 0.01, 10000),
              tr("Slope filter: column (along the view) slope below which weak candidates are "
                 "removed."));
  addWithHelp(number(QStringLiteral("CTRL_COL"), tr("Control point column slope (%)"),
                     defaults.ctrl_col_pct, 0.001, 10000),
              tr("Slope filter: column slope of the control point joining the two cut-offs, on "
                 "the perpendicular through the origin. Smaller values keep more diagonal "
                 "features; it must be below the column cut-off."));
  addWithHelp(new QgsProcessingParameterBoolean(QStringLiteral("DIAGONALS"),
                                                tr("Allow for diagonals"), defaults.diagonals),
              tr("If checked the removed region is the polygon through the control point; if "
                 "not, the whole rectangle below both cut-offs is removed."));
}

void DemViewAlgorithm::addStrokeModeParameter(const QString& help) {
  addWithHelp(choiceParameter(
                  QStringLiteral("STROKES"), tr("Strokes"), kStrokeModeNames,
                  [](StrokeMode mode) {
                    return mode == StrokeMode::drawn ? tr("Drawn (joined, smoothed, tapered)")
                                                     : tr("Exact (the thesis's, a point per cell)");
                  },
                  StrokeMode::drawn),
              help, true);
}

StrokeMode DemViewAlgorithm::readStrokeMode(const QVariantMap& parameters,
                                            QgsProcessingContext& context) const {
  return parameterAsChoice(*this, parameters, QStringLiteral("STROKES"), context, kStrokeModeNames);
}

void DemViewAlgorithm::addGeometryParameter(Geometry defaultValue) {
  addWithHelp(
      choiceParameter(
          QStringLiteral("GEOMETRY"), tr("Geometry"), kGeometryNames,
          [](Geometry g) {
            return g == Geometry::map ? tr("Map (cell centres)") : tr("Plan oblique (the sketch)");
          },
          defaultValue),
      tr("Map: strokes at the cell centres in the DEM's CRS. Plan oblique: each point moved "
         "along the view azimuth by (exaggeration / base slope) x (height - lowest height), so "
         "the strokes draw the oblique sketch in the same CRS."));
}

Geometry DemViewAlgorithm::readGeometry(const QVariantMap& parameters,
                                        QgsProcessingContext& context) const {
  return parameterAsChoice(*this, parameters, QStringLiteral("GEOMETRY"), context, kGeometryNames);
}

ViewParams DemViewAlgorithm::readView(const QVariantMap& parameters,
                                      QgsProcessingContext& context) const {
  ViewParams view;
  view.azimuth_deg = parameterAsDouble(parameters, QStringLiteral("AZIMUTH"), context);
  if (parameterDefinition(QStringLiteral("VE"))) {
    view.ve = parameterAsDouble(parameters, QStringLiteral("VE"), context);
    view.base_slope_pct = parameterAsDouble(parameters, QStringLiteral("BASE_SLOPE"), context);
  }
  return view;
}

void DemViewAlgorithm::readFilter(const QVariantMap& parameters, QgsProcessingContext& context,
                                  SilhouetteParams& params) const {
  AdaptiveParams& adaptive = params.adaptive;
  adaptive.mode =
      parameterAsChoice(*this, parameters, QStringLiteral("FILTER"), context, kFilterModeNames);
  adaptive.adapt =
      parameterAsChoice(*this, parameters, QStringLiteral("ADAPT"), context, kAdaptivityNames);
  adaptive.window = parameterAsInt(parameters, QStringLiteral("ADAPT_WINDOW"), context);
  FilterParams& filter = params.filter;
  filter.row_cut_pct = parameterAsDouble(parameters, QStringLiteral("ROW_CUT"), context);
  filter.col_cut_pct = parameterAsDouble(parameters, QStringLiteral("COL_CUT"), context);
  filter.ctrl_col_pct = parameterAsDouble(parameters, QStringLiteral("CTRL_COL"), context);
  filter.diagonals = parameterAsBool(parameters, QStringLiteral("DIAGONALS"), context);
}

void DemViewAlgorithm::logFilter(const FilterReport& r, QgsProcessingFeedback* feedback) {
  if (!feedback || r.choice.mode == FilterMode::fixed) return;
  feedback->pushInfo(tr("Slope filter adapted to the DEM: its median slope is %1 % against %2 % "
                        "on the thesis's terrain, so the cut-offs are scaled by %3: row %4 %, "
                        "column %5 %, control point %6 %.")
                         .arg(r.median_slope_pct, 0, 'g', 3)
                         .arg(kReferenceSlopePct, 0, 'g', 3)
                         .arg(r.scale, 0, 'g', 3)
                         .arg(r.cutoffs.row_cut_pct, 0, 'g', 3)
                         .arg(r.cutoffs.col_cut_pct, 0, 'g', 3)
                         .arg(r.cutoffs.ctrl_col_pct, 0, 'g', 3));
  if (r.choice.adapt == Adaptivity::local) {
    feedback->pushInfo(tr("Each neighbourhood of %1 cells scales them from %2 to %3 times the "
                          "thesis's.")
                           .arg(r.choice.window)
                           .arg(r.local_lowest, 0, 'g', 3)
                           .arg(r.local_highest, 0, 'g', 3));
  }
}

namespace {

std::string localPath(const QString& path) {
  return QFile::encodeName(path).toStdString();
}

QString qtPath(const std::string& path) {
  return QDir::toNativeSeparators(QFile::decodeName(path.c_str()));
}

}  // namespace

void DemViewAlgorithm::refuseClashingOutputs(const QVariantMap& parameters,
                                             QgsProcessingContext& context) const {
  std::vector<io::NamedFile> outputs, inputs;
  for (const QgsProcessingParameterDefinition* output : destinationParameterDefinitions()) {
    const QString target = outputTarget(*this, parameters, output->name(), context);
    // A plain path is written whole; "ogr:..." adds a layer to the file.
    outputs.push_back({output->description().toStdString(), localPath(destinationFile(target)),
                       !target.startsWith(QLatin1String("ogr:"))});
  }
  for (const QgsProcessingParameterDefinition* input : parameterDefinitions()) {
    if (input->type() != QgsProcessingParameterRasterLayer::typeName()) continue;
    const QgsRasterLayer* layer = parameterAsRasterLayer(parameters, input->name(), context);
    if (!layer) continue;
    const QString path = QgsProviderRegistry::instance()
                             ->decodeUri(layer->providerType(), layer->source())
                             .value(QStringLiteral("path"))
                             .toString();
    inputs.push_back({input->description().toStdString(), localPath(path)});
  }
  const std::optional<io::PathClash> clash = io::find_clash(outputs, inputs);
  if (!clash) return;
  const QString output = QString::fromStdString(clash->output.name);
  const QString other = QString::fromStdString(clash->other.name);
  if (clash->with_input) {
    throw QgsProcessingException(
        tr("%1 would be written into %2, the file of %3, which this algorithm reads; choose "
           "another file.")
            .arg(output, qtPath(clash->file), other));
  }
  throw QgsProcessingException(
      tr("%1 and %2 would both be written to %3, one over the other; choose different files, "
         "or save both to one GeoPackage with a layer name each.")
          .arg(other, output, qtPath(clash->file)));
}

bool DemViewAlgorithm::checkParameterValues(const QVariantMap& parameters,
                                            QgsProcessingContext& context, QString* message) const {
  if (!QgsProcessingAlgorithm::checkParameterValues(parameters, context, message)) return false;
  const LayersToLoadKept kept(context);  // the run lists what it writes
  try {
    refuseClashingOutputs(parameters, context);
    // The parameters the widgets cannot check alone (the control point below the column
    // cut-off), read by a fresh instance since reading keeps them.
    const std::unique_ptr<QgsProcessingAlgorithm> probe(create());
    withCoreErrors(
        [&] { return static_cast<DemViewAlgorithm&>(*probe).readParameters(parameters, context); });
  } catch (const QgsProcessingException& e) {
    if (message) *message = e.what();
    return false;
  }
  return true;
}

bool DemViewAlgorithm::prepareAlgorithm(const QVariantMap& parameters,
                                        QgsProcessingContext& context,
                                        QgsProcessingFeedback* feedback) {
  mAzimuth = withCoreErrors([&] { return readParameters(parameters, context); });
  refuseClashingOutputs(parameters, context);
  QgsRasterLayer* layer = parameterAsRasterLayer(parameters, QStringLiteral("INPUT"), context);
  if (!layer) throw QgsProcessingException(invalidRasterError(parameters, QStringLiteral("INPUT")));
  mRaster = std::make_unique<RasterGrid>(
      layer, parameterAsInt(parameters, QStringLiteral("BAND"), context),
      context.transformContext());
  for (const QString& note : mRaster->notes()) {
    if (feedback) feedback->pushWarning(note);
  }
  return true;
}

void DemViewAlgorithm::addWithProgress(LineOutput& output, QgsFeature& feature,
                                       QgsProcessingFeedback* feedback, std::size_t total,
                                       double from) {
  output.add(feature);
  if (feedback && ++mWritten % 500 == 0) {
    if (feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
    feedback->setProgress(from + (100.0 - from) * static_cast<double>(mWritten) /
                                     static_cast<double>(std::max<std::size_t>(1, total)));
  }
}

RasterGrid& DemViewAlgorithm::readRaster(QgsProcessingFeedback* feedback, double progressTo) {
  mWritten = 0;
  mRaster->read(mAzimuth, feedback, 0.0, progressTo);
  return *mRaster;
}

ProgressFn DemViewAlgorithm::progressBetween(QgsProcessingFeedback* feedback, double from,
                                             double to) {
  return [feedback, from, to](double fraction) {
    if (!feedback) return true;
    feedback->setProgress(from + (to - from) * fraction);
    return !feedback->isCanceled();
  };
}

SilhouetteResult DemViewAlgorithm::runSilhouettes(const SilhouetteParams& params,
                                                  QgsProcessingFeedback* feedback, double from,
                                                  double to) {
  return withCoreErrors([&] {
    SilhouetteResult result =
        sketch_held_dem(mRaster->held(), params, progressBetween(feedback, from, to));
    logFilter(result.filter, feedback);
    return result;
  });
}

void DemViewAlgorithm::releaseRaster() {
  mRaster.reset();
}

}  // namespace tsk::plugin
