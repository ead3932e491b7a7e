// A stroke of varying width as the outline a page fills: what vector art draws for a tapered
// stroke (SVG and PDF previews).
#pragma once

#include <vector>

#include "core/method/strokes.h"

namespace tsk {

// The closed outline of a line whose width at point k is widths[k]: the left side forwards, a
// point beyond the last end, the right side backwards, a point before the first end. The sides
// lie half the width either side, along each point's mean normal (held to at most twice the
// half width at sharp turns). Fewer than two distinct points give an empty outline.
std::vector<StrokePoint> tapered_outline(const std::vector<StrokePoint>& line,
                                         const std::vector<double>& widths);

}  // namespace tsk
