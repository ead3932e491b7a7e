// Processing algorithm "Silhouettes (factual and formulated)": the whole method on a raster.
#pragma once

#include <QCoreApplication>

#include "core/method/params.h"
#include "core/method/silhouettes.h"
#include "plugin/dem_view_algorithm.h"

namespace tsk::plugin {

class SilhouettesAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(SilhouettesAlgorithm)

 public:
  QString name() const override;
  QString displayName() const override;
  QStringList tags() const override;
  QString shortHelpString() const override;
  QString shortDescription() const override;
  SilhouettesAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  void addStrokeParameters();
  void readStrokes(const QVariantMap& parameters, QgsProcessingContext& context);
  // Tells what the user should know of a finished run: the DEM averaged for the scale, or why it
  // drew no stroke at all.
  void tellOutcome(const SilhouetteResult& result, const DemGrid& grid,
                   QgsProcessingFeedback& feedback) const;
  SilhouetteParams mParams;
  int mStrips = 0;
  QString mFactualId;
  QString mFormulatedId;
  QString mNote;  // the run, for the layers' metadata and the print layout (sketchNote)
};

}  // namespace tsk::plugin
