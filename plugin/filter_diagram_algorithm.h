// Processing algorithm "Slope filter diagram": column against row slope with the c-set and the
// filter's removal region (thesis figures 5.7, 5.8), as an HTML page, for tuning the filter.
#pragma once

#include "plugin/dem_view_algorithm.h"

namespace tsk::plugin {

class FilterDiagramAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(FilterDiagramAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  FilterDiagramAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;

 private:
  SilhouetteParams mParams;
};

}  // namespace tsk::plugin
