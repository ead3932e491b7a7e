// Processing algorithm "Silhouettes (factual and formulated)": the whole method on a raster.
#pragma once

#include <qgsprocessingalgorithm.h>

#include <QCoreApplication>
#include <memory>

#include "params.h"

namespace tsk::plugin {

class RasterGrid;

class SilhouettesAlgorithm : public QgsProcessingAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(SilhouettesAlgorithm)

 public:
  SilhouettesAlgorithm();
  ~SilhouettesAlgorithm() override;

  QString name() const override;
  QString displayName() const override;
  QStringList tags() const override;
  QString shortHelpString() const override;
  QString shortDescription() const override;
  QIcon icon() const override;
  QString svgIconPath() const override;
  SilhouettesAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  bool prepareAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                        QgsProcessingFeedback* feedback) override;
  QVariantMap processAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                               QgsProcessingFeedback* feedback) override;
  QVariantMap postProcessAlgorithm(QgsProcessingContext& context,
                                   QgsProcessingFeedback* feedback) override;

 private:
  SilhouetteParams readParameters(const QVariantMap& parameters,
                                  QgsProcessingContext& context) const;

  std::unique_ptr<RasterGrid> mRaster;
  SilhouetteParams mParams;
  QString mFactualId;
  QString mFormulatedId;
};

}  // namespace tsk::plugin
