// Drawn strokes, step 1: joining strokes of one class that visually continue each other, the
// thesis's open problem of "small lines that visually join into a larger feature"
// (docs/DRAWN_STROKES.md).
#pragma once

#include <vector>

#include "strokes.h"

namespace tsk {

struct JoinRule {
  double gap;        // farthest apart two ends may be, map units
  double angle_deg;  // largest angle between the two ends' directions and the step between them
};

// Joins strokes of one class end to end where an end of one lies within `rule.gap` of an end of
// another and both carry on in the same direction: the outward direction of the one end, the
// step to the other end and the inward direction of the other agree within `rule.angle_deg`.
// Each end joins at most one other, best pairs (nearest, straightest) first; a stroke never joins
// itself, directly or round a loop. Ends that meet the middle of a stroke (a T-junction) are not
// ends that meet. A joined stroke's points, vertices and chain run through its pieces in order;
// its attributes are the pieces' means weighted by their cells, its length theirs plus the gaps.
// Strokes come out in the order of their first piece in `strokes`.
std::vector<Stroke> join_strokes(std::vector<Stroke> strokes, const JoinRule& rule);

}  // namespace tsk
