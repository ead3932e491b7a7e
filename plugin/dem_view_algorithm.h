// Base of the algorithms that look at a DEM from a viewpoint: the shared DEM, view and slope
// filter parameters, their help, and reading the raster (prepared on the main thread).
#pragma once

#include <qgsprocessingalgorithm.h>

#include <QCoreApplication>
#include <memory>

#include "core/method/params.h"
#include "core/method/silhouettes.h"
#include "plugin/core_errors.h"

namespace tsk::plugin {

class LineOutput;
class RasterGrid;

class DemViewAlgorithm : public QgsProcessingAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(DemViewAlgorithm)

 public:
  DemViewAlgorithm();
  ~DemViewAlgorithm() override;
  QIcon icon() const override;
  QString svgIconPath() const override;

 protected:
  // Adds `parameter` with its help text, optionally as an advanced parameter.
  void addWithHelp(QgsProcessingParameterDefinition* parameter, const QString& help,
                   bool advanced = false);
  // A decimal number parameter from `min` to `max`, its widget showing a few decimals.
  static QgsProcessingParameterNumber* number(const QString& key, const QString& label,
                                              double value, double min, double max);
  // INPUT, BAND and AZIMUTH; with `exaggeration` also VE and BASE_SLOPE.
  void addDemAndViewParameters(bool exaggeration);
  // INPUT and BAND.
  void addDemParameters();
  // FILTER, ADAPT, ADAPT_WINDOW, ROW_CUT, COL_CUT, CTRL_COL, DIAGONALS.
  void addFilterParameters();
  // STROKES, advanced: drawn (the default) or exact strokes, explained by `help`.
  void addStrokeModeParameter(const QString& help);
  StrokeMode readStrokeMode(const QVariantMap& parameters, QgsProcessingContext& context) const;
  // GEOMETRY: map or plan oblique, `defaultValue` chosen.
  void addGeometryParameter(Geometry defaultValue);
  Geometry readGeometry(const QVariantMap& parameters, QgsProcessingContext& context) const;
  ViewParams readView(const QVariantMap& parameters, QgsProcessingContext& context) const;
  // The filter's parameters into `params`: its cut-offs and whether they adapt to the DEM.
  void readFilter(const QVariantMap& parameters, QgsProcessingContext& context,
                  SilhouetteParams& params) const;
  // Logs which cut-offs an adaptive filter chose, and why.
  static void logFilter(const FilterReport& report, QgsProcessingFeedback* feedback);

  // Subclasses read and validate their own parameters here (throw tsk::Error when invalid) and
  // return the azimuth the raster is read for.
  virtual double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) = 0;

  // Refuses parameters out of range together (readParameters) and outputs that clash
  // (refuseClashingOutputs) before the run starts, so that the dialog and batch mode say so
  // before anything is done.
  bool checkParameterValues(const QVariantMap& parameters, QgsProcessingContext& context,
                            QString* message = nullptr) const override;
  bool prepareAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                        QgsProcessingFeedback* feedback) override;

  // Adds `feature` to `output`. Every 500 features it checks for cancellation and moves progress
  // from `from` towards 100 %.
  void addWithProgress(LineOutput& output, QgsFeature& feature, QgsProcessingFeedback* feedback,
                       std::size_t total, double from);

  // Worker thread: reads the DEM oriented for the azimuth, progress 0 to `progressTo` percent.
  RasterGrid& readRaster(QgsProcessingFeedback* feedback, double progressTo);
  void releaseRaster();

  // Progress moving from `from` to `to` percent as the core reports its share done, and whether to
  // go on (Cancel).
  static ProgressFn progressBetween(QgsProcessingFeedback* feedback, double from, double to);
  // Runs the silhouette method on the raster read by readRaster(), its filter adapted to the DEM
  // (and logged), moving progress from `from` to `to` percent and stopping on cancel; the core's
  // errors become QgsProcessingException.
  SilhouetteResult runSilhouettes(const SilhouetteParams& params, QgsProcessingFeedback* feedback,
                                  double from, double to);
  // The prepared raster, not read yet (for reading strip by strip).
  RasterGrid& preparedRaster() { return *mRaster; }

 private:
  // Throws when an output would write into the file of a raster the algorithm reads, or two
  // outputs into one file not both as added layers: QGIS writes over a plain path's file whole,
  // and a layer added to the GeoPackage being read would race the reads.
  void refuseClashingOutputs(const QVariantMap& parameters, QgsProcessingContext& context) const;

  std::unique_ptr<RasterGrid> mRaster;
  double mAzimuth = 90;
  std::size_t mWritten = 0;
};

}  // namespace tsk::plugin
