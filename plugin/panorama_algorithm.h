// Processing algorithm "Panorama sketch" (docs/PANORAMA.md): the silhouettes seen from a point,
// all round or over a field of view, on the map and in the panorama, with the visibility raster.
#pragma once

#include "core/method/run_recipes.h"
#include "plugin/dem_view_algorithm.h"

namespace tsk::plugin {

class PanoramaAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(PanoramaAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  PanoramaAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  // The view's parameters; then the outputs.
  void addViewParameters();
  PanoramaResult sketch(QgsProcessingFeedback* feedback);
  // The two layers, the progress bar going from `progressFrom` to 100.
  void writeStrokes(const QVariantMap& parameters, QgsProcessingContext& context,
                    const PanoramaResult& result, double progressFrom,
                    QgsProcessingFeedback* feedback);

  // The named points to label, in the DEM's CRS (none when no layer is given).
  std::vector<NamedPoint> readPeaks(const QVariantMap& parameters, QgsProcessingContext& context);
  void writePeaks(const QVariantMap& parameters, QgsProcessingContext& context,
                  const std::vector<PeakLeader>& leaders, QgsProcessingFeedback* feedback);

  SilhouetteParams mFilter;  // the slope filter, chaining and strokes, as the silhouettes take them
  PanoramaView mView;
  double mExaggeration = 1.0;  // the panorama layer's, as the run chose it
  QString mVisibility, mMapId, mPanoramaId, mPeaksId;
  QString mNote;  // the run, for the outputs' metadata and the panorama's layout (panoramaNote)
};

}  // namespace tsk::plugin
