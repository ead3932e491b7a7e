#include "provider.h"

#include <QIcon>

#include "classification_algorithm.h"
#include "drape_algorithm.h"
#include "filter_diagram_algorithm.h"
#include "panorama_algorithm.h"
#include "plugin_paths.h"
#include "profile_plot_algorithm.h"
#include "pstroke_algorithm.h"
#include "row_slope_algorithm.h"
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
  addAlgorithm(new ProfilePlotAlgorithm());
  addAlgorithm(new ClassificationAlgorithm());
  addAlgorithm(new RowSlopeAlgorithm());
  addAlgorithm(new FilterDiagramAlgorithm());
  addAlgorithm(new DrapeAlgorithm());
  addAlgorithm(new PStrokeAlgorithm());
  addAlgorithm(new PanoramaAlgorithm());
}

}  // namespace tsk::plugin
