#include "plugin/provider.h"

#include <QIcon>

#include "plugin/classification_algorithm.h"
#include "plugin/drape_algorithm.h"
#include "plugin/filter_diagram_algorithm.h"
#include "plugin/panorama_algorithm.h"
#include "plugin/plugin_paths.h"
#include "plugin/profile_plot_algorithm.h"
#include "plugin/pstroke_algorithm.h"
#include "plugin/row_slope_algorithm.h"
#include "plugin/silhouettes_algorithm.h"

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
  addAlgorithm(new ProfilePlotAlgorithm());
  addAlgorithm(new ClassificationAlgorithm());
  addAlgorithm(new RowSlopeAlgorithm());
  addAlgorithm(new FilterDiagramAlgorithm());
  addAlgorithm(new DrapeAlgorithm());
  addAlgorithm(new PStrokeAlgorithm());
  addAlgorithm(new PanoramaAlgorithm());
}

}  // namespace tsk::plugin
