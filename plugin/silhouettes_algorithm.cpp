#include "plugin/silhouettes_algorithm.h"

#include <qgsprocessingfeedback.h>
#include <qgsprocessingoutputs.h>
#include <qgsprocessingparameters.h>
#include <qgsrasterlayer.h>

#include <algorithm>
#include <new>

#include "core/base/errors.h"
#include "core/drawn/drawing_scale.h"
#include "core/method/averaged_dem.h"
#include "core/method/silhouettes.h"
#include "plugin/choice_parameter.h"
#include "plugin/layer_style.h"
#include "plugin/line_output.h"
#include "plugin/qgis_compat.h"
#include "plugin/raster_grid.h"
#include "plugin/run_notes.h"
#include "plugin/stroke_features.h"

namespace tsk::plugin {
namespace {

// Parameter keys.
const QString kWindow = QStringLiteral("WINDOW");
const QString kMinCells = QStringLiteral("MIN_CELLS");
const QString kPlacement = QStringLiteral("PLACEMENT");
const QString kSubcell = QStringLiteral("SUBCELL");
const QString kStrips = QStringLiteral("STRIPS");
const QString kJoinGap = QStringLiteral("JOIN_GAP");
const QString kJoinAngle = QStringLiteral("JOIN_ANGLE");
const QString kSmooth = QStringLiteral("SMOOTH");
const QString kSmoothTolerance = QStringLiteral("SMOOTH_TOLERANCE");
const QString kTaper = QStringLiteral("TAPER");
const QString kDepthCue = QStringLiteral("DEPTH_CUE");
const QString kExtend = QStringLiteral("EXTEND");
const QString kDrawnFor = QStringLiteral("DRAWN_FOR");
const QString kFactual = QStringLiteral("FACTUAL");
const QString kFormulated = QStringLiteral("FORMULATED");

// Progress share of the stages with the strokes written alongside; the rest is the outputs'
// completion (a GeoPackage's spatial index).
constexpr double kCoreEnd = 95.0;

}  // namespace

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
      "Formulated silhouettes (thinner sepia, width by slope). Separate layers so each can be "
      "styled, filtered or switched off on its own, and routed separately in models. Each "
      "stroke carries: class, cells, length, mean_slope and mean_row_slope (%), mean_depth "
      "and max_depth (m, factual only), mean_dist (ground distance from the front edge of the "
      "view, in the CRS's unit) and mean_z (m).\n\n"
      "The strokes are drawn by default, as a cartographer would publish them: joined where "
      "they continue each other, smoothed within a cell of the exact chain, and stored as "
      "LineString M whose M values weigh each point (thin at the ends, thinner at the back of "
      "the view); the styles draw those weights. The advanced parameter Strokes gives the "
      "thesis's exact strokes instead.\n\n"
      "The stage figures (log and outputs), in percent of the cells with data: HIDDEN_PCT "
      "(cells hidden behind nearer terrain), OCCLUDING_PCT (occluding cells), CSET_PCT (the "
      "candidate set: back-facing cells the raised view brings into sight), FSET_PCT (the "
      "filtered set: visible candidates the slope filter keeps), TSET_PCT (the thinned set: "
      "one cell per filtered zone) and GSET_PCT (the generalised set: cells of the strokes "
      "kept, those with at least the minimum number of cells); FACTUAL_STROKES and "
      "FORMULATED_STROKES count the strokes.\n\n"
      "Reference: Beyond Factual to Formulated Silhouettes, PhD thesis, Department of "
      "Computer Science, University of Hull (chapters 4 and 5), extending the occluding "
      "contours of Visvalingam and Whelan (1998).");
}

SilhouettesAlgorithm* SilhouettesAlgorithm::createInstance() const {
  return new SilhouettesAlgorithm();
}

void SilhouettesAlgorithm::initAlgorithm(const QVariantMap&) {
  const SilhouetteParams defaults;
  addWithHelp(SharedParameters::dem());
  addWithHelp(SharedParameters::view(true));
  addWithHelp(SharedParameters::filter());
  auto add = [this](QgsProcessingParameterDefinition* p, const QString& help,
                    bool advanced = false) { addWithHelp(p, help, advanced); };
  auto integer = [](const QString& key, const QString& label, int value, int min, int max) {
    return new QgsProcessingParameterNumber(key, label, kIntegerNumber, value, false, min, max);
  };
  add(integer(kWindow, tr("Chaining window (cells)"), defaults.chain.window, 0, 1000),
      tr("Formulated strokes link cells on neighbouring profiles at most this many cells apart."));
  add(integer(kMinCells, tr("Minimum stroke cells"), defaults.chain.min_cells, 2, 1000000),
      tr("Strokes with fewer cells are dropped (generalisation). Drawn strokes keep shorter "
         "pieces only where they close a gap between longer ones."));
  addWithHelp(SharedParameters::geometry(Geometry::map));
  add(choiceParameter(
          kPlacement, tr("Formulated stroke placement"), kPlacementNames,
          [](Placement p) {
            return p == Placement::far ? tr("Far end of each zone") : tr("Near and far ends");
          },
          Placement::far),
      tr("Which cells of a filtered zone become formulated silhouette points."), true);
  add(new QgsProcessingParameterBoolean(kSubcell, tr("Sub-cell occluding points"), false),
      tr("Place factual points where the transformed profile peaks between cells instead of at "
         "cell centres (removes the thesis's halo)."),
      true);
  addStrokeParameters();
  add(integer(kStrips, tr("Profiles per strip (0: automatic)"), 0, 0, 1000000),
      tr("The DEM is read and processed this many profiles at a time, the next strip read while "
         "this one is processed, so DEMs larger than memory run too. 0 chooses 1024, more for "
         "profiles under 1024 cells (a million cells a strip), fewer for profiles over 4096 "
         "cells (four million cells a strip, at least 256), or fewer when profiles are so long "
         "that the strips would take more than 512 MB. "
         "Strips that would take more than half of this machine's memory are refused."),
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

void SilhouettesAlgorithm::addStrokeParameters() {
  const DrawnParams defaults;
  auto add = [this](const QString& key, const QString& label, double value, double min, double max,
                    const QString& help) {
    addWithHelp(SharedParameters::number(key, label, value, min, max), help, true);
  };
  addWithHelp(SharedParameters::strokeMode(
      tr("Drawn (the default): strokes a cartographer would publish. Pieces of one class that "
         "continue each other across a small gap are joined before short strokes are dropped; "
         "points lie between cells where the profile peaks or the slope breaks, and are smoothed "
         "along the stroke; every point carries a weight (its M value) that tapers the ends and "
         "thins the strokes towards the back of the view, which the layers' styles draw. Exact: "
         "the thesis's strokes, a point at each cell centre.")));
  auto* scale = new QgsProcessingParameterScale(kDrawnFor, tr("Drawn for scale"), QVariant(), true);
  scale->setMinimum(0);
  scale->setMetadata(
      {{QStringLiteral("widget_wrapper"), QVariantMap{{QStringLiteral("decimals"), 0}}}});
  addWithHelp(scale,
              tr("Drawn strokes: the scale of the map they are drawn for (1:N). The shortest "
                 "stroke (2 mm on paper), the smoothing, its tolerance and the join gap become at "
                 "least what that scale needs, strokes outlining less than N/10 000 metres of "
                 "relief are left out, and the layers' styles draw their widths true at that "
                 "scale (the renderer's reference scale). A DEM at least twice as fine as the "
                 "scale needs (cells under 0.4 mm on paper) is first averaged to it. Empty: for "
                 "no scale; every stroke is still weighed by the relief it outlines."));
  add(kJoinGap, tr("Join gap (cells)"), defaults.join_gap_cells, 0, 20,
      tr("Drawn strokes: ends of two strokes this close (in cells) are joined when their "
         "directions agree. 0 joins none."));
  add(kJoinAngle, tr("Join angle (degrees)"), defaults.join_angle_deg, 0, 90,
      tr("Drawn strokes: the largest turn between two ends' directions, and the step between "
         "them, for them to be joined."));
  add(kSmooth, tr("Smoothing (cells)"), defaults.smooth_cells, 0, 20,
      tr("Drawn strokes: the width (sigma, in cells) of the Gaussian smoothing along each "
         "stroke. 0 keeps the points where they are."));
  add(kSmoothTolerance, tr("Smoothing tolerance (cells)"), defaults.tolerance_cells, 0, 2,
      tr("Drawn strokes: no point moves farther than this (in cells) from its place on the "
         "exact chain, so smoothing never invents terrain."));
  add(kTaper, tr("Taper (share of the stroke)"), defaults.taper, 0, 0.5,
      tr("Drawn strokes: the share of a stroke's length over which each end thins."));
  add(kDepthCue, tr("Depth cue"), defaults.depth_cue, 0, 0.95,
      tr("Drawn strokes: the share of the weight strokes lose from the front of the view to "
         "its back."));
  add(kExtend, tr("Over-extension (cells)"), defaults.extend_cells, 0, 10,
      tr("Drawn strokes: each end runs on this far (in cells) along its direction, as a "
         "hand-drawn stroke does. 0: none."));
}

void SilhouettesAlgorithm::readStrokes(const QVariantMap& parameters,
                                       QgsProcessingContext& context) {
  DrawnParams& d = mParams.strokes;
  d.mode = SharedParameters::readStrokeMode(*this, parameters, context);
  d.join_gap_cells = parameterAsDouble(parameters, kJoinGap, context);
  d.join_angle_deg = parameterAsDouble(parameters, kJoinAngle, context);
  d.smooth_cells = parameterAsDouble(parameters, kSmooth, context);
  d.tolerance_cells = parameterAsDouble(parameters, kSmoothTolerance, context);
  d.taper = parameterAsDouble(parameters, kTaper, context);
  d.depth_cue = parameterAsDouble(parameters, kDepthCue, context);
  d.extend_cells = parameterAsDouble(parameters, kExtend, context);
  d.scale = parameterAsDouble(parameters, kDrawnFor, context);  // 0 when left empty
}

double SilhouettesAlgorithm::readParameters(const QVariantMap& parameters,
                                            QgsProcessingContext& context) {
  SilhouetteParams& p = mParams;
  p.view = SharedParameters::readView(*this, parameters, context);
  SharedParameters::readFilter(*this, parameters, context, p);
  p.chain.window = parameterAsInt(parameters, kWindow, context);
  p.chain.min_cells = parameterAsInt(parameters, kMinCells, context);
  p.geometry = SharedParameters::readGeometry(*this, parameters, context);
  p.placement = parameterAsChoice(*this, parameters, kPlacement, context, kPlacementNames);
  p.subcell = parameterAsBool(parameters, kSubcell, context);
  mStrips = parameterAsInt(parameters, kStrips, context);
  readStrokes(parameters, context);
  p.validate();
  return p.view.azimuth_deg;
}

QVariantMap SilhouettesAlgorithm::writeOutputs(const QVariantMap& parameters,
                                               QgsProcessingContext& context,
                                               QgsProcessingFeedback* feedback) {
  RasterGrid& raster = preparedRaster();
  const DemSource dem = raster.source();
  // The grid the run sketches: the DEM's, or for a scale far coarser than it, the DEM averaged.
  const std::size_t averaging = run_averaging(mParams, dem.grid, dem.geotransform);
  const OrientedFrame frame = withCoreErrors(
      [&] { return make_frame(averaged_grid(dem.grid, averaging), mParams.view.azimuth_deg); });
  const std::size_t strip = mStrips > 0 ? static_cast<std::size_t>(mStrips) : strip_profiles(frame);
  // Worth saying only when the DEM does not fit one strip.
  const std::size_t strips = (frame.profiles + strip - 1) / strip;
  if (feedback && strips > 1) {
    feedback->pushInfo(
        tr("Processing the DEM in %1 strips of %2 profiles.").arg(strips).arg(strip));
  }
  const QgsFields fields = strokeFields();
  const bool drawn = mParams.strokes.drawn();
  LineOutput factual(*this, parameters, kFactual, context, fields, raster.crs(), feedback, drawn);
  LineOutput formulated(*this, parameters, kFormulated, context, fields, raster.crs(), feedback,
                        drawn);
  // Each stroke goes to its output as it completes, from one thread alongside the linking, while
  // the other threads work on the next profiles. A failure or cancel discards both outputs.
  const ProgressFn progress = progressBetween(feedback, 0, kCoreEnd);
  const SilhouetteResult result = withCoreErrors([&] {
    return sketch_silhouettes(dem, mParams, strip, progress, [&](Stroke&& stroke) {
      (stroke.cls == StrokeClass::factual ? factual : formulated).add(stroke);
    });
  });
  SharedParameters::logFilter(result.filter, feedback);
  if (feedback) tellOutcome(result, dem.grid, *feedback);
  mNote = sketchNote(demName(), mParams.view, result.filter, mParams.strokes, result.averaged);
  factual.finish(mNote);
  formulated.finish(mNote);
  mFactualId = factual.destination();
  mFormulatedId = formulated.destination();

  QVariantMap outputs;
  outputs.insert(kFactual, mFactualId);
  outputs.insert(kFormulated, mFormulatedId);
  for (const StageFigure& f : stage_figures(result.stats)) {
    const QString key = QString::fromLatin1(f.key);
    outputs.insert(key.toUpper(), f.value);
    if (feedback) feedback->pushInfo(QStringLiteral("%1: %2").arg(key).arg(f.value));
  }
  releaseRaster();  // release the grid before QGIS loads the outputs
  return outputs;
}

void SilhouettesAlgorithm::tellOutcome(const SilhouetteResult& result, const DemGrid& grid,
                                       QgsProcessingFeedback& feedback) const {
  const double scale = mParams.strokes.drawn() ? mParams.strokes.scale : 0.0;
  const QString scaleText = QLocale().toString(scale, 'f', 0);
  if (result.averaged > 1) {
    const double cell = std::min(grid.dx, grid.dy) * static_cast<double>(result.averaged);
    feedback.pushInfo(tr("Drawn for 1:%L1, the DEM was averaged %L2 x %L2 cells first (to %L3 m "
                         "a cell, about 0.4 mm on paper): the scale shows nothing finer.")
                          .arg(scaleText)
                          .arg(static_cast<qulonglong>(result.averaged))
                          .arg(cell, 0, 'g', 4));
  }
  // A run that drew nothing says which stage left nothing, and which parameter to change.
  const ViewParams& view = mParams.view;
  switch (empty_run(result.stats)) {
    case EmptyRun::not_empty:
      return;
    case EmptyRun::no_valid_cell:
      feedback.pushWarning(
          tr("No strokes: every cell of the DEM is nodata (its declared nodata value, NaN, or a "
             "height of 1e30 or more): check the band, the no data value the layer or its file "
             "declares (Layer Properties > Transparency), and the band's scale."));
      return;
    case EmptyRun::nothing_seen:
      feedback.pushWarning(
          tr("No strokes: no cell of the DEM is hidden, and none slopes away from the viewer "
             "gently enough to be seen once tilted (under the base slope of %L1 % over the "
             "exaggeration of %L2, %L3 %): the DEM is flat, or faces the viewer everywhere. "
             "Another view azimuth or a larger base slope brings slopes into sight.")
              .arg(view.base_slope_pct, 0, 'g', 3)
              .arg(view.ve, 0, 'g', 3)
              .arg(view.base_slope_pct / view.ve, 0, 'g', 3));
      return;
    case EmptyRun::all_filtered:
      feedback.pushWarning(
          tr("No strokes: the slope filter removed every candidate cell, and no "
             "cell is hidden. Lower cut-offs keep more, or the slope filter "
             "adapted to the DEM scales them."));
      return;
    case EmptyRun::all_short:
      feedback.pushWarning(
          scale > 0.0
              ? tr("No strokes: every chain was shorter than the shortest stroke kept. Drawn for "
                   "1:%1, strokes under %L2 mm on paper, or outlining under %L3 m of relief, are "
                   "dropped too: a larger scale (a smaller number) keeps more.")
                    .arg(scaleText)
                    .arg(kLeastStrokeMm)
                    .arg(scale / kFullReliefPerScale * kVanishingShare, 0, 'f', 0)
              : tr("No strokes: every chain was shorter than the shortest stroke kept (%L1 "
                   "cells). A lower minimum stroke length keeps more.")
                    .arg(mParams.chain.min_cells));
      return;
  }
}

QVariantMap SilhouettesAlgorithm::postProcessAlgorithm(QgsProcessingContext& context,
                                                       QgsProcessingFeedback*) {
  // Drawn strokes get the styles that draw their weights: tapered, thinner at the back.
  const QString drawn = mParams.strokes.drawn() ? QStringLiteral("_drawn") : QString();
  const QString from = fromAzimuth(mParams.view);
  const double scale = mParams.strokes.drawn() ? mParams.strokes.scale : 0.0;
  styleOnCompletion(context, mFactualId, QStringLiteral("factual") + drawn, RampRange::style,
                    {tr("Factual silhouettes, %1").arg(from), mNote, true, nullptr, false, scale});
  styleOnCompletion(
      context, mFormulatedId, QStringLiteral("formulated") + drawn, RampRange::style,
      {tr("Formulated silhouettes, %1").arg(from), mNote, false, nullptr, false, scale});
  return {};
}

}  // namespace tsk::plugin
