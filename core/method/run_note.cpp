#include "core/method/run_note.h"

#include <sstream>

namespace tsk {

std::string run_note(const RunFacts& f) {
  std::ostringstream note;
  note.precision(4);
  const FilterParams& cut = f.filter.cutoffs;
  note << f.dem << ", band " << f.band << ". Seen from " << f.view.azimuth_deg
       << "\xc2\xb0 (azimuth), vertical exaggeration " << f.view.ve << ", base slope "
       << f.view.base_slope_pct << " %; "
       << (f.filter.choice.mode == FilterMode::fixed ? "the thesis's slope filter"
                                                     : "the slope filter adapted to the DEM")
       << ": row " << cut.row_cut_pct << " %, column " << cut.col_cut_pct << " %, control point "
       << cut.ctrl_col_pct << " %; " << (f.drawn ? "drawn strokes" : "the thesis's exact strokes")
       << ". Terrain Sketch " << f.version << ".";
  return note.str();
}

}  // namespace tsk
