// Drawn strokes, step 1: joining strokes of one class that visually continue each other, the
// thesis's open problem of "small lines that visually join into a larger feature"
// (docs/DRAWN_STROKES.md).
#pragma once

#include <cstdint>
#include <memory>
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

// Strokes of one class sorted, as they come, into the groups that joining may link, directly or
// through others. Joining one group never depends on another, so a group can be joined once no
// stroke still to come can join it (join_strokes on its members gives what it gives them among
// all the strokes).
class StrokeGrouper {
 public:
  explicit StrokeGrouper(const JoinRule& rule);
  ~StrokeGrouper();
  StrokeGrouper(const StrokeGrouper&) = delete;
  StrokeGrouper& operator=(const StrokeGrouper&) = delete;

  // Adds a stroke (its chain in profile order) to the groups of the strokes not yet taken that
  // it may join. Returns its id: ids count up from 0 in the order strokes are added.
  std::size_t add(const Stroke& stroke);
  // A stroke's group, named by its first stroke.
  std::size_t group_of(std::size_t id);
  // The last profile any stroke of group `root` reaches.
  std::int32_t reach(std::size_t root) const { return reach_[root]; }
  // The ids of group `root`'s strokes in order, into `members`; they join no stroke added later.
  void take_group(std::size_t root, std::vector<std::size_t>& members);

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct EndRecord {
    StrokePoint at;
    double dx, dy;
  };
  struct Index;
  void unite(std::size_t a, std::size_t b);

  JoinRule rule_;
  std::unique_ptr<Index> index_;
  std::vector<EndRecord> ends_;  // stroke k's start at 2k, its last point at 2k + 1
  std::vector<std::size_t> parent_, next_, tail_;
  std::vector<std::int32_t> reach_;
};

}  // namespace tsk
