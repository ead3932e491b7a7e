// Processing algorithm "P-stroke sketch" (thesis section 8.1): short strokes across the view
// where profiles bend, combined with the silhouettes' f-set.
#pragma once

#include "core/applications/pstrokes.h"
#include "plugin/dem_view_algorithm.h"
#include "plugin/layer_style.h"

namespace tsk::plugin {

class PStrokeAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(PStrokeAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  PStrokeAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  SilhouetteParams mParams;
  PStrokeParams mPStrokes;
  QString mOutput;
  RunNote mNote;
};

}  // namespace tsk::plugin
