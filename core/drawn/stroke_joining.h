// Drawn strokes, step 1: joining strokes of one class that visually continue each other, the
// thesis's open problem of "small lines that visually join into a larger feature"
// (docs/DRAWN_STROKES.md).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "core/method/strokes.h"

namespace tsk {

struct JoinRule {
  double gap;        // farthest apart two ends may be, map units
  double angle_deg;  // largest angle between the two ends' directions and the step between them
  // Pieces of fewer cells are left off the ends of a joined stroke (0: none are).
  int least_piece_cells = 0;
};

// Joins strokes of one class end to end where an end of one lies within `rule.gap` of an end of
// another and both carry on in the same direction: the outward direction of the one end, the
// step to the other end and the inward direction of the other agree within `rule.angle_deg`.
// Each end joins at most one other, best pairs (nearest, straightest) first; a stroke never joins
// itself, directly or round a loop. Ends that meet the middle of a stroke (a T-junction) are not
// ends that meet. A joined stroke's points, vertices and chain run through its pieces in order;
// its attributes are the pieces' means weighted by their cells, its length theirs plus the gaps.
// Pieces shorter than `rule.least_piece_cells` stay only where they close a gap between longer
// ones: they are left off a joined stroke's ends (the thesis's cartographers kept small lines that
// link into larger features, section 7.2; alone, SPEC's generalisation drops them). Strokes come
// out in the order of their first piece in `strokes`.
std::vector<Stroke> join_strokes(std::vector<Stroke> strokes, const JoinRule& rule);

// Asks the processor for what StrokeGrouper::add reads of `piece` first (its chain's end, its
// points' ends), for a caller to do so for the next piece while it adds this one: pieces made on
// another thread, or visited out of the order they were made in, miss the cache otherwise.
inline void prefetch_piece_ends(const Stroke& piece) {
  if (!piece.chain.empty()) __builtin_prefetch(&piece.chain.back());
  if (!piece.points.empty()) {
    __builtin_prefetch(piece.points.data());
    __builtin_prefetch(&piece.points.back());
  }
}

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
  // Asks the processor for what add(stroke) will look up first, for a caller to do so for the
  // next stroke while it adds this one (the stroke's ends must be in the cache already:
  // prefetch_piece_ends, a step earlier).
  void prefetch(const Stroke& stroke) const;
  // A stroke's group, named by its first stroke.
  std::size_t group_of(std::size_t id);
  // The last profile any stroke of group `root` reaches.
  std::int32_t reach(std::size_t root) const { return record(root).reach; }
  // The ids of group `root`'s strokes in order, into `members`; they join no stroke added later.
  void take_group(std::size_t root, std::vector<std::size_t>& members);
  // Tells the grouper that every stroke before `id` has been taken, so that it may forget them:
  // what it holds follows the strokes in flight, not all the strokes of a run.
  void forget_before(std::size_t id);
  // How many strokes' records it holds.
  std::size_t strokes_held() const { return records_.size(); }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  static constexpr std::size_t kForgetAtLeast = 1024;  // strokes' records, to forget at once
  struct EndRecord {
    StrokePoint at;
    double dx, dy;
  };
  // A stroke's place in its group (ids), its group's reach if it is the root, whether its group
  // has been taken, and its ends.
  struct Record {
    std::size_t parent, next, tail;
    std::int32_t reach;
    bool taken;
    EndRecord ends[2];  // its start, its last point
  };
  struct Index;
  Record& record(std::size_t id) { return records_[id - first_held_]; }
  const Record& record(std::size_t id) const { return records_[id - first_held_]; }
  void unite(std::size_t a, std::size_t b);

  JoinRule rule_;
  double angle_cos_;  // of the rule's angle, to compare directions by
  std::unique_ptr<Index> index_;
  std::vector<Record> records_;  // of strokes first_held_, first_held_ + 1, ...
  std::size_t first_held_ = 0;
  std::vector<std::uint32_t> near_;  // the ends near a stroke's two ends, its storage reused
};

}  // namespace tsk
