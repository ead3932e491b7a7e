// Processing algorithm "Profile plot (ridgelines)": cross-sections across the view in
// plan-oblique geometry with hidden parts removed (thesis figure 4.6).
#pragma once

#include "plugin/dem_view_algorithm.h"
#include "plugin/layer_style.h"

namespace tsk::plugin {

class ProfilePlotAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(ProfilePlotAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  ProfilePlotAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  ViewParams mView;
  int mEvery = 10;
  QString mOutput;
  RunNote mNote;
};

}  // namespace tsk::plugin
