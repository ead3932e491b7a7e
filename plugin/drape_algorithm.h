// Processing algorithm "Drape raster (plan oblique)": any raster on the DEM's grid projected into
// plan-oblique space with hidden areas removed, under the plan-oblique silhouettes.
#pragma once

#include <memory>

#include "core/applications/drape.h"
#include "plugin/dem_view_algorithm.h"

class QgsRasterDataProvider;

namespace tsk::plugin {

class RasterGrid;

class DrapeAlgorithm : public DemViewAlgorithm {
  Q_DECLARE_TR_FUNCTIONS(DrapeAlgorithm)

 public:
  DrapeAlgorithm();
  ~DrapeAlgorithm() override;
  QString name() const override;
  QString displayName() const override;
  QString shortHelpString() const override;
  DrapeAlgorithm* createInstance() const override;

 protected:
  void initAlgorithm(const QVariantMap& configuration = QVariantMap()) override;
  double readParameters(const QVariantMap& parameters, QgsProcessingContext& context) override;
  bool prepareAlgorithm(const QVariantMap& parameters, QgsProcessingContext& context,
                        QgsProcessingFeedback* feedback) override;
  QVariantMap writeOutputs(const QVariantMap& parameters, QgsProcessingContext& context,
                           QgsProcessingFeedback* feedback) override;

 private:
  // The drape's layout over the DEM read (its flags let go once it is laid out).
  PlanObliqueDrape layOut(const RasterGrid& raster, QgsProcessingFeedback* feedback) const;
  // Band `band` of the raster to drape, read through QGIS (rows x cols, NaN for nodata).
  HeightGrid readSourceBand(int band, std::size_t rows, std::size_t cols,
                            QgsProcessingFeedback* feedback) const;

  ViewParams mView;
  std::unique_ptr<QgsRasterDataProvider> mSource;
  int mSourceBands = 0;
  QString mSourceName;  // as the user knows it, for the drape's description
};

}  // namespace tsk::plugin
