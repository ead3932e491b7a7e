#include "plugin/panorama_layout.h"

#include <qgsexpressioncontextutils.h>
#include <qgslayoutitemmap.h>
#include <qgslayoutmanager.h>
#include <qgsmaplayer.h>
#include <qgsprintlayout.h>
#include <qgsproject.h>
#include <qgsreadwritecontext.h>

#include <QDomDocument>
#include <QFile>
#include <algorithm>
#include <memory>

#include "plugin/plugin_paths.h"

namespace tsk::plugin {
namespace {

constexpr double kMapWidth = 400, kMapTop = 24;  // millimetres on the template's A3 page

// `title`, or `title` (2), (3), ... as the first free name among the project's layouts.
QString freeName(const QgsLayoutManager& layouts, const QString& title) {
  QString name = title;
  for (int k = 2; layouts.layoutByName(name); ++k)
    name = QStringLiteral("%1 (%2)").arg(title).arg(k);
  return name;
}

}  // namespace

PanoramaLayout::PanoramaLayout(QString title, QString note)
    : mTitle(std::move(title)), mNote(std::move(note)) {}

QgsPrintLayout* PanoramaLayout::made(QgsProject& project) {
  if (!mName.isEmpty())
    return dynamic_cast<QgsPrintLayout*>(project.layoutManager()->layoutByName(mName));
  // The page comes from the plugin's template: its labels say the layout's name and its variable
  // (Debian's label header cannot be included, and the template is what a designer edits).
  QFile file(layoutPath(QStringLiteral("terrain_sketch_panorama")));
  QDomDocument document;
  if (!file.open(QIODevice::ReadOnly) || !document.setContent(&file)) return nullptr;
  auto layout = std::make_unique<QgsPrintLayout>(&project);
  bool ok = false;
  layout->loadFromTemplate(document, QgsReadWriteContext(), true, &ok);
  if (!ok) return nullptr;
  mName = freeName(*project.layoutManager(), mTitle);
  layout->setName(mName);
  // The manager owns the layout once it takes it; one it refuses stays ours, and goes.
  if (!project.layoutManager()->addLayout(layout.get())) return nullptr;
  return layout.release();
}

void PanoramaLayout::add(QgsProject& project, QgsMapLayer& layer, bool panorama) {
  QgsPrintLayout* layout = made(project);
  auto* map = layout ? qobject_cast<QgsLayoutItemMap*>(layout->itemById(QStringLiteral("panorama")))
                     : nullptr;
  if (!map) return;
  QList<QgsMapLayer*> layers = map->layers();
  // Peak labels over the strokes, whichever loads first.
  if (panorama) {
    layers.append(&layer);
  } else {
    layers.prepend(&layer);
  }
  map->setLayers(layers);
  if (!panorama) return;
  // The whole panorama with a margin, as tall on the page as its (exaggerated) angles are.
  QgsRectangle extent = layer.extent();
  if (extent.isEmpty()) extent = QgsRectangle(0, -1, 360, 1);
  extent.grow(0.03 * extent.width());
  const double height = std::clamp(kMapWidth * extent.height() / extent.width(), 20.0, 240.0);
  // In the frame's proportions about the same centre (zoomToExtent transforms through the
  // project's CRS, which the panorama has none to).
  const double half = 0.5 * extent.width() * height / kMapWidth;
  const double middle = extent.center().y();
  extent.setYMinimum(middle - half);
  extent.setYMaximum(middle + half);
  map->setCrs(layer.crs());
  map->attemptResize(QgsLayoutSize(kMapWidth, height));
  map->setExtent(extent);
  if (QgsLayoutItem* note = layout->itemById(QStringLiteral("note")))
    note->attemptMove(QgsLayoutPoint(note->positionWithUnits().x(), kMapTop + height + 4));
  const double degreesPerCm = 10.0 * map->extent().width() / kMapWidth;
  QgsExpressionContextUtils::setLayoutVariable(
      layout, QStringLiteral("terrain_sketch_panorama_note"),
      tr("%1 10 mm on the page: %L2° of azimuth.").arg(mNote).arg(degreesPerCm, 0, 'g', 3));
  layout->refresh();
}

}  // namespace tsk::plugin
