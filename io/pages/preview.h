// A picture of the oblique sketch (the thesis's profile plot) without QGIS: PNG, or vector art
// (SVG, PDF) for print, Illustrator or a pen plotter.
#pragma once

#include <string>

#include "core/method/silhouettes.h"
#include "io/pages/sketch_page.h"
#include "io/pages/vector_art.h"

namespace tsk::io {

// Renders the strokes of `result` as seen from the viewpoint (far side up): factual strokes bold
// black, formulated strokes thinner, on white; drawn strokes tapered and weighted for depth. The
// extension of `path` picks the format: .png a picture, .svg or .pdf vector art (sketch_page.h,
// vector_art.h). Whole or not at all. Returns the plotter's figures for a plotter page.
PlotterReport write_preview(const std::string& path, const SilhouetteResult& result,
                            const HeightGrid& z, const OrientedFrame& frame,
                            const GeoTransform& geotransform, const ViewParams& view,
                            Geometry geometry, const PageOptions& options = {});

// Writes a laid-out page in the format of `path`'s extension, as write_preview does.
PlotterReport write_page(const std::string& path, const SketchPage& page,
                         const PageOptions& options = {});

}  // namespace tsk::io
