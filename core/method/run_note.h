// The run in one sentence, for what its outputs record of it (a GeoPackage's description, the
// vector art's <desc>): the DEM, the view, the filter it ran and the strokes. The QGIS plugin
// words the same in the user's language.
#pragma once

#include <cstddef>
#include <string>

#include "core/method/adaptive_filter.h"
#include "core/method/params.h"

namespace tsk {

struct RunFacts {
  std::string dem;  // as the user named it: a file's name, a layer's
  int band = 1;
  ViewParams view;
  FilterReport filter;  // the filter the run ran
  bool drawn = true;    // drawn strokes, or the thesis's exact ones
  std::string version;  // of Terrain Sketch
  double scale = 0.0;   // drawn strokes: drawn for 1:scale (0: for no scale)
  // Drawn for a scale far coarser than the DEM: the cells a side it was averaged by first.
  std::size_t averaged = 1;
};

// "jacksboro_utm16n.tif, band 1. Seen from 250° (azimuth), vertical exaggeration 2.5, base slope
// 40 %; the slope filter adapted to the DEM: row 20 %, column 12 %, control point 8.73 %; drawn
// strokes. Terrain Sketch 0.1.0." ("drawn strokes for 1:250000" with a scale; "drawn strokes for
// 1:1000000 from the DEM averaged 5 x 5 cells" when averaged for it).
std::string run_note(const RunFacts& facts);

// The same for another product of the view (`product`: "P-strokes", "Profile lines"), without the
// strokes' mode, and without the filter unless `with_filter`: "jacksboro_utm16n.tif, band 1.
// P-strokes seen from 250° (azimuth), vertical exaggeration 2.5, base slope 40 %; the slope filter
// adapted to the DEM: row 20 %, column 12 %, control point 8.73 %. Terrain Sketch 0.1.0."
std::string product_note(const RunFacts& facts, const std::string& product, bool with_filter);

}  // namespace tsk
