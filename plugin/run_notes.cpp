#include "plugin/run_notes.h"

#include <QCoreApplication>

namespace tsk::plugin {
namespace {

QString tr(const char* text) {
  return QCoreApplication::translate("RunNotes", text);
}

}  // namespace

QString filterPhrase(const FilterReport& filter) {
  const FilterParams& cut = filter.cutoffs;
  return tr("%1: row %L2 %, column %L3 %, control point %L4 %")
      .arg(filter.choice.mode == FilterMode::fixed ? tr("the thesis's slope filter")
                                                   : tr("the slope filter adapted to the DEM"))
      .arg(cut.row_cut_pct, 0, 'g', 3)
      .arg(cut.col_cut_pct, 0, 'g', 3)
      .arg(cut.ctrl_col_pct, 0, 'g', 3);
}

QString fromAzimuth(const ViewParams& view) {
  return tr("from %L1°").arg(view.azimuth_deg, 0, 'g', 4);
}

QString sketchNote(const QString& dem, const ViewParams& view, const FilterReport& filter,
                   const DrawnParams& strokes) {
  const QString drawn = strokes.scale > 0
                            ? tr("drawn strokes for 1:%L1").arg(strokes.scale, 0, 'f', 0)
                            : tr("drawn strokes");
  return tr("%1. Seen from %L2° (azimuth), vertical exaggeration %L3, base slope %L4 %; %5; %6. "
            "Terrain Sketch %7.")
      .arg(dem)
      .arg(view.azimuth_deg, 0, 'g', 4)
      .arg(view.ve, 0, 'g', 3)
      .arg(view.base_slope_pct, 0, 'g', 3)
      .arg(filterPhrase(filter))
      .arg(strokes.drawn() ? drawn : tr("the thesis's exact strokes"))
      .arg(QStringLiteral(TSK_VERSION));
}

RunNote productNote(const QString& dem, const QString& product, const ViewParams& view,
                    const FilterReport* filter) {
  const QString seen =
      tr("%1. %2 seen from %L3° (azimuth), vertical exaggeration %L4, base slope %L5 %")
          .arg(dem, product)
          .arg(view.azimuth_deg, 0, 'g', 4)
          .arg(view.ve, 0, 'g', 3)
          .arg(view.base_slope_pct, 0, 'g', 3);
  RunNote note;
  note.title = tr("%1, %2").arg(product, fromAzimuth(view));
  note.abstract = (filter ? seen + QStringLiteral("; ") + filterPhrase(*filter) : seen) +
                  tr(". Terrain Sketch %1.").arg(QStringLiteral(TSK_VERSION));
  return note;
}

}  // namespace tsk::plugin
