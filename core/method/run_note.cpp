#include "core/method/run_note.h"

#include <iomanip>
#include <sstream>

namespace tsk {

namespace {

// "<dem>, band <n>. <Product seen|Seen> from <azimuth>° (azimuth), vertical exaggeration <ve>,
// base slope <b> %"
void put_view(std::ostream& note, const RunFacts& f, const std::string& product) {
  note << f.dem << ", band " << f.band << ". " << (product.empty() ? "Seen" : product + " seen")
       << " from " << f.view.azimuth_deg << "\xc2\xb0 (azimuth), vertical exaggeration "
       << f.view.ve << ", base slope " << f.view.base_slope_pct << " %";
}

// "; <filter>: row <r> %, column <c> %, control point <p> %"
void put_filter(std::ostream& note, const FilterReport& filter) {
  const FilterParams& cut = filter.cutoffs;
  note << "; "
       << (filter.choice.mode == FilterMode::fixed ? "the thesis's slope filter"
                                                   : "the slope filter adapted to the DEM")
       << ": row " << cut.row_cut_pct << " %, column " << cut.col_cut_pct << " %, control point "
       << cut.ctrl_col_pct << " %";
}

}  // namespace

std::string run_note(const RunFacts& f) {
  std::ostringstream note;
  note.precision(4);
  put_view(note, f, "");
  put_filter(note, f.filter);
  note << "; " << (f.drawn ? "drawn strokes" : "the thesis's exact strokes");
  if (f.drawn && f.scale > 0.0) note << " for 1:" << std::fixed << std::setprecision(0) << f.scale;
  if (f.drawn && f.averaged > 1)
    note << " from the DEM averaged " << f.averaged << " x " << f.averaged << " cells";
  note << ". Terrain Sketch " << f.version << ".";
  return note.str();
}

std::string product_note(const RunFacts& f, const std::string& product, bool with_filter) {
  std::ostringstream note;
  note.precision(4);
  put_view(note, f, product);
  if (with_filter) put_filter(note, f.filter);
  note << ". Terrain Sketch " << f.version << ".";
  return note.str();
}

}  // namespace tsk
