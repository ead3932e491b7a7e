#include "plugin/panorama_algorithm.h"

#include <qgsfeaturerequest.h>
#include <qgsgeometry.h>
#include <qgspoint.h>
#include <qgsprocessingfeedback.h>
#include <qgsprocessingparameters.h>
#include <qgsprocessingutils.h>
#include <qgsrasterlayer.h>

#include <memory>

#include "core/base/errors.h"
#include "plugin/layer_style.h"
#include "plugin/line_output.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"
#include "plugin/raster_output.h"
#include "plugin/run_notes.h"
#include "plugin/stroke_features.h"

namespace tsk::plugin {
namespace {

const QString kObserver = QStringLiteral("OBSERVER");
const QString kObserverHeight = QStringLiteral("OBSERVER_HEIGHT");
const QString kMaxDistance = QStringLiteral("MAX_DISTANCE");
const QString kAzimuthFrom = QStringLiteral("AZIMUTH_FROM");
const QString kAzimuthTo = QStringLiteral("AZIMUTH_TO");
const QString kRefraction = QStringLiteral("REFRACTION");
const QString kExaggeration = QStringLiteral("PANORAMA_EXAGGERATION");
const QString kSamplesPerCell = QStringLiteral("SAMPLES_PER_CELL");
const QString kMinCells = QStringLiteral("MIN_CELLS");
const QString kWindow = QStringLiteral("WINDOW");
const QString kMapOutput = QStringLiteral("MAP_OUTPUT");
const QString kPanoramaOutput = QStringLiteral("PANORAMA_OUTPUT");
const QString kVisibility = QStringLiteral("VISIBILITY");
const QString kPeaks = QStringLiteral("PEAKS");
const QString kPeakNames = QStringLiteral("PEAK_NAMES");
const QString kPeaksOutput = QStringLiteral("PEAKS_OUTPUT");

}  // namespace

QString PanoramaAlgorithm::name() const {
  return QStringLiteral("panorama");
}
QString PanoramaAlgorithm::displayName() const {
  return tr("Panorama sketch");
}

QString PanoramaAlgorithm::shortHelpString() const {
  return tr(
      "The silhouettes of the terrain seen from a viewpoint, as a panorama board draws them: "
      "rays are cast from the observer all round (or over a field of view), every ray a "
      "profile of the silhouette method. Factual silhouettes are the occluding edges, the "
      "skyline and the ridges in front of it; Formulated silhouettes are back-facing slopes "
      "that the sight line, descending onto them, still reaches, kept by the slope filter. "
      "Heights are lowered by the earth's curvature, lessened by refraction. The strokes come "
      "on the map (the DEM's CRS) and in the panorama (x the azimuth, y the elevation angle, "
      "in degrees, without a CRS), far strokes drawn lighter.");
}

PanoramaAlgorithm* PanoramaAlgorithm::createInstance() const {
  return new PanoramaAlgorithm();
}

void PanoramaAlgorithm::addViewParameters() {
  const PanoramaView defaults;
  addWithHelp(new QgsProcessingParameterPoint(kObserver, tr("Observer")),
              tr("Where the viewer stands: click it on the map. It must lie on the DEM, on a "
                 "cell with data."));
  addWithHelp(SharedParameters::number(kObserverHeight, tr("Observer height (m)"),
                                       defaults.observer_height, 0, 1e5),
              tr("The eye's height above the ground at the observer, in metres."));
  // Optional: not given, the range is the whole DEM (a number's widget cannot be left empty).
  auto* range = SharedParameters::number(kMaxDistance, tr("Range (map units)"), 1, 0.001, 1e9);
  range->setFlags(range->flags() | kOptional);
  range->setDefaultValue(QVariant());
  addWithHelp(range, tr("The farthest distance drawn, in the DEM's map units; when not given, "
                        "the whole DEM."));
  addWithHelp(
      SharedParameters::number(kAzimuthFrom, tr("Field of view from (degrees)"), 0, -360, 720),
      tr("The field of view turns clockwise from this azimuth (from grid north) to the "
         "next. 0 to 360, the default, is all round."));
  addWithHelp(
      SharedParameters::number(kAzimuthTo, tr("Field of view to (degrees)"), 360, -360, 720),
      tr("The azimuth the field of view ends at; equal azimuths make an empty field."));
  addWithHelp(SharedParameters::number(kRefraction, tr("Refraction coefficient"),
                                       defaults.refraction, 0, 0.99),
              tr("How much refraction lessens the earth's curvature (k): heights are lowered by "
                 "(1 - k) d² / 2R at distance d. 0.13 is the usual value over land."),
              true);
  addWithHelp(new QgsProcessingParameterNumber(kSamplesPerCell, tr("Samples per cell"),
                                               kIntegerNumber, 1, false, 1, kMostSamplesPerCell),
              tr("Samples along each ray per DEM cell. More follow the terrain between the "
                 "cells' centres, so that what is seen depends less on the DEM's grid (a DEM "
                 "warped to another CRS sees the same), at the square of this times the work."),
              true);
  addWithHelp(SharedParameters::number(kExaggeration, tr("Panorama exaggeration"), 0, 0, 50),
              tr("How many times as tall as its azimuths are wide the Panorama layer draws its "
                 "elevation angles, 1 to 50. 0, the default, chooses up to 5 so that a wide field "
                 "of view is no flat strip. The Panorama layout draws it so."));
}

void PanoramaAlgorithm::initAlgorithm(const QVariantMap&) {
  addWithHelp(SharedParameters::dem());
  addViewParameters();
  addWithHelp(SharedParameters::filter());
  const ChainParams chain;
  addWithHelp(new QgsProcessingParameterNumber(kMinCells, tr("Minimum stroke length (samples)"),
                                               kIntegerNumber, chain.min_cells, false, 1, 1000000),
              tr("Strokes of fewer samples are dropped; at N samples per cell, strokes of fewer "
                 "than N times this."),
              true);
  addWithHelp(new QgsProcessingParameterNumber(kWindow, tr("Formulated chaining window (samples)"),
                                               kIntegerNumber, chain.window, false, 0, 1000),
              tr("How far along the next ray a formulated chain may step."), true);
  addWithHelp(SharedParameters::strokeMode(
      tr("Drawn (the default): a stroke is cut where its chain leaps along the rays, since a "
         "leap draws no line on the terrain. Exact: the thesis's strokes, each chain whole.")));
  addWithHelp(new QgsProcessingParameterFeatureSink(kMapOutput, tr("Panorama strokes on the map"),
                                                    kLineLayer),
              tr("The strokes in the DEM's CRS, with their class, distance and azimuths."));
  addWithHelp(new QgsProcessingParameterFeatureSink(kPanoramaOutput, tr("Panorama"), kLineLayer),
              tr("The same strokes in the panorama: x the azimuth and y the elevation angle, in "
                 "degrees, without a CRS. Open it in a map of its own."));
  addWithHelp(new QgsProcessingParameterFeatureSource(
                  kPeaks, tr("Peaks to label"), {static_cast<int>(kPointLayer)}, QVariant(), true),
              tr("Optional: named points, the summits of a gazetteer. Those whose top the "
                 "observer sees are labelled in the panorama."));
  addWithHelp(
      new QgsProcessingParameterField(kPeakNames, tr("Peak name field"), QStringLiteral("name"),
                                      kPeaks, kAnyField, false, true),
      tr("The field of the peaks holding their names."));
  addWithHelp(new QgsProcessingParameterFeatureSink(kPeaksOutput, tr("Peak labels"), kLineLayer,
                                                    QVariant(), true, false),
              tr("The peaks in sight as leaders in the panorama, from each top straight up to "
                 "its label, with the name, distance, azimuth and elevation."));
  auto* visibility = new QgsProcessingParameterRasterDestination(kVisibility, tr("Visibility"),
                                                                 QVariant(), true, false);
  addWithHelp(visibility, tr("Optional: a raster on the DEM's grid, 1 where the ground is seen, "
                             "0 where it is hidden, nodata out of range."));
}

double PanoramaAlgorithm::readParameters(const QVariantMap& parameters,
                                         QgsProcessingContext& context) {
  SharedParameters::readFilter(*this, parameters, context, mFilter);
  mFilter.chain.min_cells = parameterAsInt(parameters, kMinCells, context);
  mFilter.chain.window = parameterAsInt(parameters, kWindow, context);
  mFilter.strokes.mode = SharedParameters::readStrokeMode(*this, parameters, context);
  mFilter.validate();
  QgsRasterLayer* dem = parameterAsRasterLayer(parameters, QStringLiteral("INPUT"), context);
  const QgsCoordinateReferenceSystem crs = dem ? dem->crs() : QgsCoordinateReferenceSystem();
  const QgsPointXY observer = parameterAsPoint(parameters, kObserver, context, crs);
  if (dem && !dem->extent().contains(observer))
    throw Error(tr("The observer lies outside the DEM: choose a point on it.").toStdString());
  PanoramaView& view = mView;
  view.observer_x = observer.x();
  view.observer_y = observer.y();
  view.observer_height = parameterAsDouble(parameters, kObserverHeight, context);
  const QVariant range = parameters.value(kMaxDistance);
  view.max_distance = range.isValid() && !range.toString().isEmpty()
                          ? parameterAsDouble(parameters, kMaxDistance, context)
                          : 0.0;
  view.azimuth_from = parameterAsDouble(parameters, kAzimuthFrom, context);
  view.azimuth_to = parameterAsDouble(parameters, kAzimuthTo, context);
  view.refraction = parameterAsDouble(parameters, kRefraction, context);
  view.exaggeration = parameterAsDouble(parameters, kExaggeration, context);
  view.samples_per_cell = parameterAsInt(parameters, kSamplesPerCell, context);
  view.validate();
  return 90.0;  // the DEM read as it lies: the view from the west is its own grid
}

PanoramaResult PanoramaAlgorithm::sketch(QgsProcessingFeedback* feedback) {
  readRaster(feedback, 20);
  const ProgressFn progress = progressBetween(feedback, 20, 80);
  const PanoramaChoice choice{mView, mFilter, !mVisibility.isEmpty()};
  return withCoreErrors([&] {
    PanoramaRun run = sketch_panorama_on(preparedRaster().held(), choice, progress);
    SharedParameters::logFilter(run.filter, feedback);
    mExaggeration = run.exaggeration;
    return std::move(run.result);
  });
}

void PanoramaAlgorithm::writeStrokes(const QVariantMap& parameters, QgsProcessingContext& context,
                                     const PanoramaResult& result, double progressFrom,
                                     QgsProcessingFeedback* feedback) {
  QgsFields fields = strokeFields();
  fields.append(makeField(QStringLiteral("azimuth_min"), FieldKind::Real));
  fields.append(makeField(QStringLiteral("azimuth_max"), FieldKind::Real));
  LineOutput map(*this, parameters, kMapOutput, context, fields, preparedRaster().crs(), feedback);
  LineOutput panorama(*this, parameters, kPanoramaOutput, context, fields,
                      QgsCoordinateReferenceSystem(), feedback);
  for (const PanoramaStroke& s : result.strokes) {
    QgsFeature feature = strokeFeature(s.map, fields);
    // strokeFeature fills the stroke fields only: the azimuths follow them.
    QgsAttributes attributes = feature.attributes();
    attributes << s.azimuth_min << s.azimuth_max;
    feature.setAttributes(attributes);
    addWithProgress(map, feature, feedback, 2 * result.strokes.size(), progressFrom);
    feature.setGeometry(lineGeometry(exaggerated(s.view, mExaggeration)));
    addWithProgress(panorama, feature, feedback, 2 * result.strokes.size(), progressFrom);
  }
  map.finish(mNote);
  panorama.finish(mNote);
  mMapId = map.destination();
  mPanoramaId = panorama.destination();
}

std::vector<NamedPoint> PanoramaAlgorithm::readPeaks(const QVariantMap& parameters,
                                                     QgsProcessingContext& context) {
  std::vector<NamedPoint> peaks;
  const std::unique_ptr<QgsProcessingFeatureSource> source(
      parameterAsSource(parameters, kPeaks, context));
  if (!source) return peaks;
  const QString field = parameterAsString(parameters, kPeakNames, context);
  const int index = source->fields().lookupField(field);
  if (index < 0)
    throw QgsProcessingException(tr("The peaks have no field '%1' for their names.").arg(field));
  // The points in the DEM's CRS.
  QgsFeatureRequest request;
  request.setDestinationCrs(preparedRaster().crs(), context.transformContext());
  QgsFeature feature;
  for (QgsFeatureIterator it = source->getFeatures(request); it.nextFeature(feature);) {
    const QString name = feature.attribute(index).toString();
    for (auto part = feature.geometry().const_parts_begin();
         part != feature.geometry().const_parts_end(); ++part) {
      const auto* point = qgsgeometry_cast<const QgsPoint*>(*part);
      if (point) peaks.push_back({name.toStdString(), point->x(), point->y()});
    }
  }
  return peaks;
}

void PanoramaAlgorithm::writePeaks(const QVariantMap& parameters, QgsProcessingContext& context,
                                   const std::vector<PeakLeader>& leaders,
                                   QgsProcessingFeedback* feedback) {
  QgsFields fields;
  fields.append(makeField(QStringLiteral("name"), FieldKind::Text));
  for (const char* name : {"distance", "azimuth", "elevation"})
    fields.append(makeField(QString::fromLatin1(name), FieldKind::Real));
  LineOutput output(*this, parameters, kPeaksOutput, context, fields,
                    QgsCoordinateReferenceSystem(), feedback);
  for (const PeakLeader& l : leaders) {
    QgsFeature feature(fields);
    QgsAttributes attributes;
    attributes << QString::fromStdString(l.peak.name) << l.peak.distance << l.peak.azimuth_deg
               << l.peak.elevation_deg;
    feature.setAttributes(attributes);
    feature.setGeometry(lineGeometry(exaggerated({l.top, l.label}, mExaggeration)));
    output.add(feature);
  }
  output.finish(mNote);
  mPeaksId = output.destination();
}

QVariantMap PanoramaAlgorithm::writeOutputs(const QVariantMap& parameters,
                                            QgsProcessingContext& context,
                                            QgsProcessingFeedback* feedback) {
  // Read here, not with the other parameters, which the dialog's check reads too: a temporary
  // output read is a new file named in a new folder, left empty by a check.
  mVisibility = parameterAsOutputLayer(parameters, kVisibility, context);
  const PanoramaResult result = sketch(feedback);
  mNote = panoramaNote(demName(), mView, mExaggeration);
  const RasterGrid& raster = preparedRaster();
  // Asked for as the dialog asks (a QgsProcessingOutputLayerDefinition, whose toString() is
  // empty) or as processing.run does (a path).
  const bool labelPeaks = !outputTarget(*this, parameters, kPeaksOutput, context).isEmpty();
  const std::vector<PeakLeader> leaders =
      labelPeaks ? lead_peaks(result, see_peaks(raster.oriented(), raster.geotransform(),
                                                result.rays, readPeaks(parameters, context)))
                 : std::vector<PeakLeader>();
  // The raster first: the line outputs, once finished, are whole.
  const double strokesFrom = mVisibility.isEmpty() ? 80 : 85;
  if (!mVisibility.isEmpty()) {
    const Grid<std::uint8_t> seen = withCoreErrors([&] {
      return visibility_raster(result, raster.oriented().rows(), raster.oriented().cols(),
                               raster.geotransform(), 0,
                               progressBetween(feedback, 80, strokesFrom));
    });
    writeVisibilityRaster(mVisibility, seen, raster, mNote);
  }
  if (feedback && feedback->isCanceled()) throw QgsProcessingException(tr("Cancelled."));
  writeStrokes(parameters, context, result, strokesFrom, feedback);
  if (labelPeaks) writePeaks(parameters, context, leaders, feedback);
  releaseRaster();
  QVariantMap outputs = {{kMapOutput, mMapId}, {kPanoramaOutput, mPanoramaId}};
  if (!mVisibility.isEmpty()) outputs.insert(kVisibility, mVisibility);
  if (labelPeaks) outputs.insert(kPeaksOutput, mPeaksId);
  return outputs;
}

QVariantMap PanoramaAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                    QgsProcessingFeedback*) {
  const auto layout = std::make_shared<PanoramaLayout>(tr("Panorama"), mNote);
  // The layers keep the names the user gave them; their metadata hold the run.
  styleOnCompletion(context, mMapId, QStringLiteral("panorama_map"), RampRange::style,
                    {{}, mNote, false, nullptr, false});
  styleOnCompletion(context, mPanoramaId, QStringLiteral("panorama"), RampRange::style,
                    {{}, mNote, false, layout, true});
  styleOnCompletion(context, mPeaksId, QStringLiteral("panorama_peaks"), RampRange::style,
                    {{}, mNote, false, layout, false});
  styleOnCompletion(context, mVisibility, QStringLiteral("visibility"), RampRange::style,
                    {{}, mNote, false, nullptr, false});
  return {};
}

}  // namespace tsk::plugin
