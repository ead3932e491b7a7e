#include "provider.h"

#include <QIcon>

#include "plugin_paths.h"
#include "silhouettes_algorithm.h"

namespace tsk::plugin {

QString TerrainSketchProvider::id() const {
  return QStringLiteral("terrainsketch");
}
QString TerrainSketchProvider::name() const {
  return tr("Terrain sketch");
}
QString TerrainSketchProvider::longName() const {
  return tr("Terrain sketch: factual and formulated silhouettes");
}
QIcon TerrainSketchProvider::icon() const {
  return QIcon(iconPath());
}
QString TerrainSketchProvider::svgIconPath() const {
  return iconPath();
}

void TerrainSketchProvider::loadAlgorithms() {
  addAlgorithm(new SilhouettesAlgorithm());
}

}  // namespace tsk::plugin
