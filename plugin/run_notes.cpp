#include "plugin/run_notes.h"

#include <QCoreApplication>
#include <QLocale>

namespace tsk::plugin {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("RunNotes", text);
}

// A number as %L would write it. The notes fill their placeholders in one pass (QString's
// multi-argument arg()), so that a '%1' in a layer's name is never taken for a placeholder.
QString number(double value, int precision) {
  return QLocale().toString(value, 'g', precision);
}

}  // namespace

QString filterPhrase(const FilterReport& filter) {
  const FilterParams& cut = filter.cutoffs;
  return tr("%1: row %L2 %, column %L3 %, control point %L4 %")
      .arg(filter.choice.mode == FilterMode::fixed ? tr("the thesis's slope filter")
                                                   : tr("the slope filter adapted to the DEM"),
           number(cut.row_cut_pct, 3), number(cut.col_cut_pct, 3), number(cut.ctrl_col_pct, 3));
}

QString fromAzimuth(const ViewParams& view) {
  return tr("from %L1°").arg(number(view.azimuth_deg, 4));
}

QString sketchNote(const QString& dem, const ViewParams& view, const FilterReport& filter,
                   const DrawnParams& strokes, std::size_t averaged) {
  QString drawn = strokes.scale > 0
                      ? tr("drawn strokes for 1:%L1").arg(QLocale().toString(strokes.scale, 'f', 0))
                      : tr("drawn strokes");
  if (averaged > 1)
    drawn += tr(" from the DEM averaged %L1 x %L1 cells").arg(static_cast<qulonglong>(averaged));
  return tr("%1. Seen from %L2° (azimuth), vertical exaggeration %L3, base slope %L4 %; %5; %6. "
            "Terrain Sketch %7.")
      .arg(dem, number(view.azimuth_deg, 4), number(view.ve, 3), number(view.base_slope_pct, 3),
           filterPhrase(filter), strokes.drawn() ? drawn : tr("the thesis's exact strokes"),
           QStringLiteral(TSK_VERSION));
}

QString panoramaNote(const QString& dem, const PanoramaView& view, double exaggeration) {
  const QString sampled =
      view.samples_per_cell > 1
          ? tr("; %L1 samples per cell along each ray").arg(view.samples_per_cell)
          : QString();
  const QString drawn =
      exaggeration == 1.0
          ? tr("to the same scale as azimuths")
          : tr("%L1 times as tall as azimuths are wide").arg(number(exaggeration, 3));
  return tr("%1. Seen from %L2, %L3, %L4 m above the ground, from %L5° to %L6° (azimuths from "
            "grid north); elevation angles drawn %7%9. Terrain Sketch %8.")
      .arg(dem, QLocale().toString(view.observer_x, 'f', 0),
           QLocale().toString(view.observer_y, 'f', 0), number(view.observer_height, 4),
           number(view.azimuth_from, 4), number(view.azimuth_to, 4), drawn,
           QStringLiteral(TSK_VERSION), sampled);
}

RunNote productNote(const QString& dem, const QString& product, const ViewParams& view,
                    const FilterReport* filter) {
  const QString seen =
      tr("%1. %2 seen from %L3° (azimuth), vertical exaggeration %L4, base slope %L5 %")
          .arg(dem, product, number(view.azimuth_deg, 4), number(view.ve, 3),
               number(view.base_slope_pct, 3));
  RunNote note;
  note.title = tr("%1, %2").arg(product, fromAzimuth(view));
  note.abstract = (filter ? seen + QStringLiteral("; ") + filterPhrase(*filter) : seen) +
                  tr(". Terrain Sketch %1.").arg(QStringLiteral(TSK_VERSION));
  return note;
}

}  // namespace tsk::plugin
