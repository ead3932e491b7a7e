// The sketch page as vector art: SVG for Inkscape and Illustrator, PDF for print.
#pragma once

#include <string>
#include <vector>

#include "core/drawn/pen_plot.h"
#include "io/pages/sketch_page.h"

namespace tsk::io {

// What a plotter's page cost the pen: its travel in the air before and after ordering, in page
// units, and its paths before and after merging (for each class, then summed).
struct PlotterReport {
  double travel_before = 0.0, travel_after = 0.0;
  std::size_t strokes = 0, paths = 0;
};

// The page as a pen plotter draws it: each class's strokes as single lines, merged where they
// meet and ordered to cut the pen's travel.
struct PlotterPage {
  std::vector<PenPlan> classes;  // formulated, then factual
  PlotterReport report;
};
PlotterPage plan_plotter_page(const SketchPage& page);

// One group (an Illustrator or Inkscape layer; in PDF an optional content group, which
// Illustrator opens as a layer) per class, formulated first so that factual strokes lie on top,
// one path per stroke: strokes of one width as lines, tapered strokes as filled outlines. With a
// plotter page, its single-line paths instead. Whole or not at all.
void write_svg(const std::string& path, const SketchPage& page, const PlotterPage* plotter);
void write_pdf(const std::string& path, const SketchPage& page, const PlotterPage* plotter);

}  // namespace tsk::io
