// The "Terrain sketch" processing provider: lists the plugin's algorithms.
#pragma once

#include <qgsprocessingprovider.h>

#include <QCoreApplication>

namespace tsk::plugin {

class TerrainSketchProvider : public QgsProcessingProvider {
  Q_DECLARE_TR_FUNCTIONS(TerrainSketchProvider)

 public:
  QString id() const override;
  QString name() const override;
  QString longName() const override;
  QIcon icon() const override;
  QString svgIconPath() const override;

 protected:
  void loadAlgorithms() override;
};

}  // namespace tsk::plugin
