// Base of the algorithms that look at a DEM from a viewpoint: a run's life in QGIS (parameters
// checked together before the run, outputs checked against inputs, the raster prepared on the
// main thread and read on the worker), composed with the parameters it shares with the others
// (shared_parameters.h).
#pragma once

#include <qgsprocessingalgorithm.h>

#include <QCoreApplication>
#include <memory>

#include "core/method/params.h"
#include "core/method/silhouettes.h"
#include "plugin/core_errors.h"
#include "plugin/shared_parameters.h"

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
  // Adds the shared parameters (shared_parameters.h) an algorithm composes.
  void addWithHelp(const HelpedParameter& parameter);
  void addWithHelp(const std::vector<HelpedParameter>& parameters);

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

  // Worker thread: runs writeOutputs and then puts every output it wrote to a file in place
  // together (io/write/output_set.h), so that a run that fails, is cancelled or is killed leaves
  // the earlier outputs of the same names whole. A run that must wait for another writing one of
  // them says so, and Cancel ends the wait.
  QVariantMap processAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                               QgsProcessingFeedback* feedback) final;
  // The algorithm's work and outputs, returning its results.
  virtual QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) = 0;

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
  // The DEM as the user knows it: its layer's name and band ("jacksboro_utm16n, band 1").
  const QString& demName() const { return mDemName; }

 private:
  // Throws when an output would write into the file of a raster the algorithm reads, or two
  // outputs into one file not both as added layers: QGIS writes over a plain path's file whole,
  // and a layer added to the GeoPackage being read would race the reads. Throws too for a raster
  // output in another format than GeoTIFF.
  void refuseClashingOutputs(const QVariantMap& parameters, QgsProcessingContext& context) const;

  std::unique_ptr<RasterGrid> mRaster;
  QString mDemName;
  double mAzimuth = 90;
  std::size_t mWritten = 0;
};

}  // namespace tsk::plugin
