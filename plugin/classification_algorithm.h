// Processing algorithm "Silhouette stages (classification raster)": the per-cell stage of the
// method on the DEM grid, for the map views of thesis figures 5.4 and 5.10.
#pragma once

#include "plugin/dem_view_algorithm.h"
#include "plugin/layer_style.h"

namespace tsk::plugin {

class ClassificationAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(ClassificationAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  ClassificationAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  SilhouetteParams mParams;
  QString mOutput;
  RunNote mNote;
};

}  // namespace tsk::plugin
