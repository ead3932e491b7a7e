#include "silhouettes_algorithm.h"

#include <qgsprocessingfeedback.h>
#include <qgsprocessingoutputs.h>
#include <qgsrasterlayer.h>

#include <QIcon>
#include <new>

#include "errors.h"
#include "layer_style.h"
#include "plugin_paths.h"
#include "qgis_compat.h"
#include "raster_grid.h"
#include "silhouettes.h"
#include "stroke_features.h"

namespace tsk::plugin {
namespace {

// Parameter keys.
const QString kInput = QStringLiteral("INPUT");
const QString kBand = QStringLiteral("BAND");
const QString kAzimuth = QStringLiteral("AZIMUTH");
const QString kVe = QStringLiteral("VE");
const QString kBaseSlope = QStringLiteral("BASE_SLOPE");
const QString kRowCut = QStringLiteral("ROW_CUT");
const QString kColCut = QStringLiteral("COL_CUT");
const QString kCtrl = QStringLiteral("CTRL_COL");
const QString kDiagonals = QStringLiteral("DIAGONALS");
const QString kWindow = QStringLiteral("WINDOW");
const QString kMinCells = QStringLiteral("MIN_CELLS");
const QString kGeometry = QStringLiteral("GEOMETRY");
const QString kPlacement = QStringLiteral("PLACEMENT");
const QString kSubcell = QStringLiteral("SUBCELL");
const QString kFactual = QStringLiteral("FACTUAL");
const QString kFormulated = QStringLiteral("FORMULATED");

// Progress shares: reading the raster, the core stages, writing the strokes.
constexpr double kReadEnd = 25.0;
constexpr double kCoreEnd = 90.0;

}  // namespace

SilhouettesAlgorithm::SilhouettesAlgorithm() = default;
SilhouettesAlgorithm::~SilhouettesAlgorithm() = default;

QString SilhouettesAlgorithm::name() const {
  return QStringLiteral("silhouettes");
}

QString SilhouettesAlgorithm::displayName() const {
  return tr("Silhouettes (factual and formulated)");
}

QStringList SilhouettesAlgorithm::tags() const {
  return tr("silhouette,occluding contour,sketch,oblique,panorama,block diagram,plan oblique,"
            "terrain,dem,hidden")
      .split(',');
}

QString SilhouettesAlgorithm::shortDescription() const {
  return tr("Draws the silhouette lines of a DEM seen obliquely from above as vector strokes.");
}

QString SilhouettesAlgorithm::shortHelpString() const {
  return tr(
      "Finds the lines a cartographer sketches first when drawing terrain seen obliquely "
      "from above.\n\n"
      "Factual Silhouettes are occluding contours: cells beyond which the terrain hides "
      "what lies behind it, in a parallel view with vertical exaggeration and a base slope "
      "added along the line of sight. Formulated Silhouettes are back-facing slopes that "
      "the raised view brings into sight (the candidate set), kept where the slope filter "
      "finds them significant (outside the weak/weak corner of column slope against row "
      "slope), thinned to the cell furthest from the viewer and chained across profiles.\n\n"
      "The DEM's heights must be in metres and its CRS projected in metres; a geographic "
      "DEM is refused. Any view azimuth works; the four cardinal ones are exact.\n\n"
      "Two line outputs: Factual silhouettes (styled bold black, width by hidden depth) and "
      "Formulated silhouettes (thinner grey, width by slope). Separate layers so each can be "
      "styled, filtered or switched off on its own, and routed separately in models. Each "
      "stroke carries: class, cells, length, mean_slope and mean_row_slope (%), mean_depth "
      "and max_depth (m, factual only), mean_dist (distance from the front of the view) "
      "and mean_z.\n\n"
      "Reference: Beyond Factual to Formulated Silhouettes, PhD thesis, Department of "
      "Computer Science, University of Hull (chapters 4 and 5), extending the occluding "
      "contours of Visvalingam and Whelan (1998).");
}

QIcon SilhouettesAlgorithm::icon() const {
  return QIcon(iconPath());
}
QString SilhouettesAlgorithm::svgIconPath() const {
  return iconPath();
}

SilhouettesAlgorithm* SilhouettesAlgorithm::createInstance() const {
  return new SilhouettesAlgorithm();
}

void SilhouettesAlgorithm::initAlgorithm(const QVariantMap&) {
  const SilhouetteParams defaults;
  auto add = [this](QgsProcessingParameterDefinition* p, const QString& help,
                    bool advanced = false) {
    p->setHelp(help);
    if (advanced) p->setFlags(p->flags() | kAdvanced);
    addParameter(p);
  };
  auto number = [](const QString& key, const QString& label, double value, double min, double max,
                   bool integer = false) {
    return new QgsProcessingParameterNumber(key, label, integer ? kIntegerNumber : kDoubleNumber,
                                            value, false, min, max);
  };
  add(new QgsProcessingParameterRasterLayer(kInput, tr("Elevation (DEM)")),
      tr("Digital elevation model with heights in metres, in a projected CRS in metres."));
  add(new QgsProcessingParameterBand(kBand, tr("Band"), 1, kInput),
      tr("The band holding the heights."));
  add(number(kAzimuth, tr("View azimuth (degrees)"), defaults.view.azimuth_deg, 0, 360),
      tr("Compass bearing the viewer faces, clockwise from grid north: 0 (from the south), 90 "
         "(from the west, the default), 180 (from the north), 270 (from the east). These four "
         "are exact; any other azimuth resamples the DEM bilinearly onto a grid aligned with "
         "the line of sight, and the strokes are mapped back exactly into the DEM's CRS."));
  add(number(kVe, tr("Vertical exaggeration"), defaults.view.ve, 0.01, 1000),
      tr("Factor applied to heights before occlusion is computed."));
  add(number(kBaseSlope, tr("Base slope (%)"), defaults.view.base_slope_pct, 0.01, 10000),
      tr("Slope added along the line of sight, in percent: the view elevation angle is "
         "atan(base slope) above the exaggerated terrain (40 % = 21.8 degrees)."));
  add(number(kRowCut, tr("Row slope cut-off (%)"), defaults.filter.row_cut_pct, 0.01, 10000),
      tr("Slope filter: row (across the view) slope below which weak candidates are removed; "
         "20 % is Macgregor's critical slope."));
  add(number(kColCut, tr("Column slope cut-off (%)"), defaults.filter.col_cut_pct, 0.01, 10000),
      tr("Slope filter: column (along the view) slope below which weak candidates are removed."));
  add(number(kCtrl, tr("Control point column slope (%)"), defaults.filter.ctrl_col_pct, 0.001,
             10000),
      tr("Slope filter: column slope of the control point joining the two cut-offs, on the "
         "perpendicular through the origin. Smaller values keep more diagonal features; it must "
         "be below the column cut-off."));
  add(new QgsProcessingParameterBoolean(kDiagonals, tr("Allow for diagonals"),
                                        defaults.filter.diagonals),
      tr("If checked the removed region is the polygon through the control point; if not, the "
         "whole rectangle below both cut-offs is removed."));
  add(number(kWindow, tr("Chaining window (cells)"), defaults.chain.window, 0, 1000, true),
      tr("Formulated strokes link cells on neighbouring profiles at most this many cells apart."));
  add(number(kMinCells, tr("Minimum stroke cells"), defaults.chain.min_cells, 2, 1000000, true),
      tr("Strokes with fewer cells are dropped (generalisation)."));
  add(new QgsProcessingParameterEnum(kGeometry, tr("Geometry"),
                                     {tr("Map (cell centres)"), tr("Plan oblique (the sketch)")},
                                     false, 0),
      tr("Map: strokes at the cell centres in the DEM's CRS. Plan oblique: each point moved "
         "along the view azimuth by (exaggeration / base slope) x (height - lowest height), so "
         "the strokes draw the oblique sketch in the same CRS."));
  add(new QgsProcessingParameterEnum(kPlacement, tr("Formulated stroke placement"),
                                     {tr("Far end of each zone"), tr("Near and far ends")}, false,
                                     0),
      tr("Which cells of a filtered zone become formulated silhouette points."), true);
  add(new QgsProcessingParameterBoolean(kSubcell, tr("Sub-cell occluding points"), false),
      tr("Place factual points where the transformed profile peaks between cells instead of at "
         "cell centres (removes the thesis's halo)."),
      true);
  add(new QgsProcessingParameterFeatureSink(kFactual, tr("Factual silhouettes"), kLineLayer),
      tr("Occluding contours as line strokes."));
  add(new QgsProcessingParameterFeatureSink(kFormulated, tr("Formulated silhouettes"), kLineLayer),
      tr("Formulated silhouettes as line strokes."));
  for (const StageFigure& f : stage_figures(StageStats{})) {
    addOutput(new QgsProcessingOutputNumber(QString::fromLatin1(f.key).toUpper(),
                                            QString::fromLatin1(f.key)));
  }
}

SilhouetteParams SilhouettesAlgorithm::readParameters(const QVariantMap& parameters,
                                                      QgsProcessingContext& context) const {
  SilhouetteParams p;
  p.view.azimuth_deg = parameterAsDouble(parameters, kAzimuth, context);
  p.view.ve = parameterAsDouble(parameters, kVe, context);
  p.view.base_slope_pct = parameterAsDouble(parameters, kBaseSlope, context);
  p.filter.row_cut_pct = parameterAsDouble(parameters, kRowCut, context);
  p.filter.col_cut_pct = parameterAsDouble(parameters, kColCut, context);
  p.filter.ctrl_col_pct = parameterAsDouble(parameters, kCtrl, context);
  p.filter.diagonals = parameterAsBool(parameters, kDiagonals, context);
  p.chain.window = parameterAsInt(parameters, kWindow, context);
  p.chain.min_cells = parameterAsInt(parameters, kMinCells, context);
  p.geometry =
      parameterAsEnum(parameters, kGeometry, context) == 1 ? Geometry::oblique : Geometry::map;
  p.placement = parameterAsEnum(parameters, kPlacement, context) == 1 ? Placement::near_and_far
                                                                      : Placement::far;
  p.subcell = parameterAsBool(parameters, kSubcell, context);
  return p;
}

bool SilhouettesAlgorithm::prepareAlgorithm(const QVariantMap& parameters,
                                            QgsProcessingContext& context,
                                            QgsProcessingFeedback* feedback) {
  mParams = readParameters(parameters, context);
  try {
    mParams.validate();
  } catch (const Error& e) {
    throw QgsProcessingException(QString::fromStdString(e.what()));
  }
  QgsRasterLayer* layer = parameterAsRasterLayer(parameters, kInput, context);
  if (!layer) throw QgsProcessingException(invalidRasterError(parameters, kInput));
  mRaster = std::make_unique<RasterGrid>(layer, parameterAsInt(parameters, kBand, context),
                                         context.transformContext());
  for (const QString& note : mRaster->notes()) {
    if (feedback) feedback->pushWarning(note);
  }
  return true;
}

QVariantMap SilhouettesAlgorithm::processAlgorithm(const QVariantMap& parameters,
                                                   QgsProcessingContext& context,
                                                   QgsProcessingFeedback* feedback) {
  mRaster->read(mParams.view.azimuth_deg, feedback, 0.0, kReadEnd);
  SilhouetteResult result;
  try {
    result = run_silhouettes(mRaster->oriented(), mRaster->frame(), mRaster->geotransform(),
                             mParams, [feedback](double fraction) {
                               if (!feedback) return true;
                               feedback->setProgress(kReadEnd + (kCoreEnd - kReadEnd) * fraction);
                               return !feedback->isCanceled();
                             });
  } catch (const Cancelled&) {
    throw QgsProcessingException(tr("Cancelled."));
  } catch (const Error& e) {
    throw QgsProcessingException(QString::fromStdString(e.what()));
  } catch (const std::bad_alloc&) {
    throw QgsProcessingException(tr("Not enough memory for this raster."));
  }

  const QgsFields fields = strokeFields();
  std::unique_ptr<QgsFeatureSink> factual(parameterAsSink(parameters, kFactual, context, mFactualId,
                                                          fields, kLineString, mRaster->crs()));
  if (!factual) throw QgsProcessingException(invalidSinkError(parameters, kFactual));
  std::unique_ptr<QgsFeatureSink> formulated(parameterAsSink(
      parameters, kFormulated, context, mFormulatedId, fields, kLineString, mRaster->crs()));
  if (!formulated) throw QgsProcessingException(invalidSinkError(parameters, kFormulated));

  const double total = std::max<std::size_t>(1, result.strokes.size());
  std::size_t written = 0;
  for (const Stroke& stroke : result.strokes) {
    const bool isFactual = stroke.cls == StrokeClass::factual;
    QgsFeature feature = strokeFeature(stroke, fields);
    QgsFeatureSink* sink = isFactual ? factual.get() : formulated.get();
    if (!sink->addFeature(feature, QgsFeatureSink::FastInsert)) {
      throw QgsProcessingException(
          writeFeatureError(sink, parameters, isFactual ? kFactual : kFormulated));
    }
    if (feedback && ++written % 1000 == 0) {
      if (feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
      feedback->setProgress(kCoreEnd + (100.0 - kCoreEnd) * written / total);
    }
  }
  factual.reset();
  formulated.reset();

  QVariantMap outputs;
  outputs.insert(kFactual, mFactualId);
  outputs.insert(kFormulated, mFormulatedId);
  for (const StageFigure& f : stage_figures(result.stats)) {
    const QString key = QString::fromLatin1(f.key);
    outputs.insert(key.toUpper(), f.value);
    if (feedback) feedback->pushInfo(QStringLiteral("%1: %2").arg(key).arg(f.value));
  }
  mRaster.reset();  // release the grid before QGIS loads the outputs
  return outputs;
}

QVariantMap SilhouettesAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                       QgsProcessingFeedback*) {
  styleOnCompletion(context, mFactualId, QStringLiteral("factual"));
  styleOnCompletion(context, mFormulatedId, QStringLiteral("formulated"));
  return {};
}

}  // namespace tsk::plugin
