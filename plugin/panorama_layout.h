// A print layout of its own for a panorama, whose layer is in no CRS of the map (azimuths across,
// elevation angles up: in the DEM's project, Zoom to Layer gave 1:6.7 billion and "Invalid map
// settings"): an A3 page with a map of the panorama and its peak labels drawn to fit it, a title
// and a note of the view with its scale. Made as the run's panorama layer loads, completed as its
// peaks do.
#pragma once

#include <QCoreApplication>
#include <QString>

class QgsMapLayer;
class QgsProject;
class QgsPrintLayout;

namespace tsk::plugin {

class PanoramaLayout {
  Q_DECLARE_TR_FUNCTIONS(PanoramaLayout)

 public:
  // `title` names the layout (made unique in the project) and heads its page; `note` says the view.
  PanoramaLayout(QString title, QString note);

  // Adds `layer` to the layout in `project`, making the layout first if need be: the panorama's
  // strokes (`panorama`) set the map's extent; its peak labels go above them.
  void add(QgsProject& project, QgsMapLayer& layer, bool panorama);

 private:
  QgsPrintLayout* made(QgsProject& project);

  QString mTitle, mNote;
  QString mName;  // of the layout made, once it is
};

}  // namespace tsk::plugin
