// Drawn strokes, before joining: a chain cut where it leaps along the line of sight. Factual
// chaining links occluding cells whose hidden zones overlap, so a chain may step from one ridge to
// another far behind it; the exact stroke draws that step as a long straight line, which no
// cartographer would draw.
#pragma once

#include <vector>

#include "strokes.h"

namespace tsk {

// Appends to `pieces` the parts of `stroke` (a drawn stroke with its vertices) between steps
// longer than `max_step` map units, each with its attributes worked out from its own cells as
// StrokeBuilder works them out; the stroke whole when it has no such step.
void split_at_leaps(Stroke&& stroke, double max_step, std::vector<Stroke>& pieces);

}  // namespace tsk
