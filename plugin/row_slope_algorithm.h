// Processing algorithm "Row slope map": |slope across the line of sight| in percent, the backdrop
// of thesis section 6.2 (light where flat across the view, dark where steep).
#pragma once

#include "plugin/dem_view_algorithm.h"
#include "plugin/layer_style.h"

namespace tsk::plugin {

class RowSlopeAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(RowSlopeAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  RowSlopeAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  ViewParams mView;
  QString mOutput;
  RunNote mNote;
};

}  // namespace tsk::plugin
