// A picture of the oblique sketch (the thesis's profile plot) without QGIS: PNG, or vector art
// (SVG, PDF) for print, Illustrator or a pen plotter.
#pragma once

#include <string>

#include "core/method/silhouettes.h"
#include "io/pages/sketch_page.h"
#include "io/pages/vector_art.h"

namespace tsk::io {

// The most pixels a PNG preview holds: drawing one takes 6 bytes a pixel (about 400 MB here).
constexpr double kMaxPreviewPixels = 64e6;
// A paper page's PNG preview is drawn at this many dots per inch.
constexpr double kPreviewDpi = 150;

// Throws Error, naming the size and the memory it would take, when a PNG preview of `width` x
// `height` pixels would hold more than kMaxPreviewPixels.
void check_png_pixels(double width, double height);
// The same for a paper page of `size` (parse_page_size) drawn at kPreviewDpi.
void check_png_page(const PageSize& size);

// Writes a laid-out page (SketchLayout) as seen from the viewpoint (far side up): factual strokes
// bold black, formulated strokes thinner, on white; drawn strokes tapered and weighted for depth.
// The extension of `path` picks the format: .png a picture, .svg or .pdf vector art
// (vector_art.h). Whole or not at all. Returns the plotter's figures for a plotter page. A picture
// reports its drawing to `progress`, and a false answer throws Cancelled.
PlotterReport write_page(const std::string& path, const SketchPage& page,
                         const PageOptions& options = {}, const ProgressFn& progress = {});

}  // namespace tsk::io
