// A picture of the oblique sketch (the thesis's profile plot) without QGIS.
#pragma once

#include <string>

#include "silhouettes.h"

namespace tsk::io {

struct PreviewOptions {
  int width_px = 1600;
};

// Renders the strokes of `result` as seen from the viewpoint (far side up): factual strokes bold
// black, formulated strokes thinner, on white. Writes a PNG, or for a .svg name vector art (a
// layer per class, a path per stroke), whole or not at all.
void write_preview(const std::string& path, const SilhouetteResult& result, const HeightGrid& z,
                   const OrientedFrame& frame, const ViewParams& view,
                   const PreviewOptions& options = {});

}  // namespace tsk::io
