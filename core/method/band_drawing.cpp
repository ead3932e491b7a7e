// Drawing inside a band (bands.h): the groups of drawn pieces that no other band can join are
// drawn by the band itself, so that a cluster's client draws only what lies near the bands' edges.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_set>

#include "core/drawn/drawn_strokes.h"
#include "core/method/bands.h"

namespace tsk {
namespace {

// Where the chains crossing a band's edges have cells: squares as wide as the join gap. An end
// that no such square around it holds lies farther than the gap from every cell of those chains,
// so from every end of their pieces, which the client cuts from them.
class CrossingCells {
 public:
  CrossingCells(const std::vector<BandPiece>& pieces, StrokeClass cls, double gap) : side_(gap) {
    for (const BandPiece& piece : pieces)
      if (piece.cls == cls)
        for (const StrokeCell& cell : piece.cells) squares_.insert(key(square(cell.point)));
  }
  // Whether a cell of a crossing chain may lie within the gap of `at`.
  bool near(StrokePoint at) const {
    const auto [x, y] = square(at);
    for (std::int64_t dy = -1; dy <= 1; ++dy)
      for (std::int64_t dx = -1; dx <= 1; ++dx)
        if (squares_.count(key({x + dx, y + dy}))) return true;
    return false;
  }

 private:
  std::pair<std::int64_t, std::int64_t> square(StrokePoint at) const {
    return {static_cast<std::int64_t>(std::floor(at.x / side_)),
            static_cast<std::int64_t>(std::floor(at.y / side_))};
  }
  // Squares that share a key (beyond 2^31 squares apart) only make ends look nearer.
  static std::uint64_t key(std::pair<std::int64_t, std::int64_t> s) {
    return (static_cast<std::uint64_t>(s.first) << 32) ^
           (static_cast<std::uint64_t>(s.second) & 0xffffffffu);
  }
  double side_;
  std::unordered_set<std::uint64_t> squares_;
};

// The pieces of class `cls` the drawing keeps, as indices into sketch.strokes in the run's order.
std::vector<std::size_t> pieces_in_order(const BandSketch& sketch, StrokeClass cls) {
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < sketch.strokes.size(); ++k)
    if (sketch.strokes[k].cls == cls && sketch.strokes[k].cells >= kLeastDrawnCells)
      order.push_back(k);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return sketch.keys[a] < sketch.keys[b]; });
  return order;
}

// Whether a piece's group may be joined by a piece of another band: an end of it near the band's
// edges, or near a cell of a chain that crosses them (cut into pieces by the client).
class OpenToOtherBands {
 public:
  OpenToOtherBands(const BandSketch& sketch, StrokeClass cls, const DrawingSetup& setup,
                   std::size_t profiles)
      : crossing_(sketch.pieces, cls, join_rule(setup).gap),
        reach_(join_reach_profiles(setup)),
        edge_before_(static_cast<double>(sketch.first) - 1.0),
        edge_after_(static_cast<double>(sketch.first + sketch.count)),
        before_(sketch.first > 0),
        after_(sketch.first + sketch.count < profiles) {}
  bool operator()(const Stroke& piece) const {
    return near_edge(piece.chain.front().p) || near_edge(piece.chain.back().p) ||
           crossing_.near(piece.points.front()) || crossing_.near(piece.points.back());
  }

 private:
  // An end on profile p may meet an end of another band's profile only reach_ profiles away.
  bool near_edge(std::int32_t p) const {
    const double q = static_cast<double>(p);
    return (before_ && q - edge_before_ <= reach_) || (after_ && edge_after_ - q <= reach_);
  }
  CrossingCells crossing_;
  double reach_, edge_before_, edge_after_;
  bool before_, after_;
};

// Groups the pieces `order` names as the drawing does and moves those of the groups no other band
// can join out of sketch.strokes (marking them in `taken`), in the order of their first pieces. A
// group is taken once no piece still to add can reach it, as StrokeDrawer takes settled groups,
// so that the grouper holds the pieces in flight rather than the whole band's.
StrokeGroups closed_groups(BandSketch& sketch, StrokeClass cls,
                           const std::vector<std::size_t>& order, const DrawingSetup& setup,
                           std::size_t profiles, std::vector<char>& taken) {
  StrokeGroups groups;
  const auto move_group = [&](const std::vector<std::size_t>& members, std::size_t first) {
    for (const std::size_t m : members) {
      groups.pieces.push_back(std::move(sketch.strokes[order[m]]));
      taken[order[m]] = 1;
    }
    groups.ends.push_back(groups.pieces.size());
    groups.firsts.push_back(first);
  };
  const JoinRule rule = join_rule(setup);
  std::vector<std::size_t> members;
  // Without a gap nothing joins: every piece is a group of its own that no band can reach.
  if (rule.gap <= 0.0) {
    for (std::size_t n = 0; n < order.size(); ++n) move_group(members = {n}, n);
    return groups;
  }
  // frontier[n]: the first profile a piece from the n-th on reaches.
  std::vector<std::int32_t> frontier(order.size() + 1, std::numeric_limits<std::int32_t>::max());
  for (std::size_t n = order.size(); n-- > 0;)
    frontier[n] = std::min(frontier[n + 1], sketch.strokes[order[n]].chain.front().p);
  const OpenToOtherBands open_to_others(sketch, cls, setup, profiles);
  const double reach = join_reach_profiles(setup);
  StrokeGrouper grouper(rule);
  std::vector<char> open(order.size(), 0), grouped(order.size(), 0);
  std::size_t first_left = 0;  // the first piece whose group is still open to pieces to come
  const auto take_settled = [&](std::size_t added, double frontier_profile) {
    for (; first_left < added; ++first_left) {
      if (grouped[first_left]) continue;
      if (!(static_cast<double>(grouper.reach(first_left)) < frontier_profile - reach)) break;
      grouper.take_group(first_left, members);
      bool group_open = false;
      for (const std::size_t m : members) group_open |= open[m], grouped[m] = 1;
      if (!group_open) move_group(members, first_left);
    }
    grouper.forget_before(first_left);
  };
  for (std::size_t n = 0; n < order.size(); ++n) {
    take_settled(n, static_cast<double>(frontier[n]));
    // In the order of their keys, the pieces lie scattered over the band's strokes.
    if (n + 2 < order.size()) __builtin_prefetch(&sketch.strokes[order[n + 2]]);
    if (n + 1 < order.size()) prefetch_piece_ends(sketch.strokes[order[n + 1]]);
    const Stroke& piece = sketch.strokes[order[n]];
    grouper.add(piece);
    open[n] = open_to_others(piece);
  }
  take_settled(order.size(), std::numeric_limits<double>::infinity());
  return groups;
}

// Draws the groups of class `cls` that no other band can join into sketch.drawn, marking their
// pieces (and those the drawing drops) in `taken`.
void draw_class(BandSketch& sketch, const DrawingSetup& setup, std::size_t profiles,
                StrokeClass cls, std::vector<char>& taken) {
  for (std::size_t k = 0; k < sketch.strokes.size(); ++k)
    if (sketch.strokes[k].cls == cls && sketch.strokes[k].cells < kLeastDrawnCells) taken[k] = 1;
  const std::vector<std::size_t> order = pieces_in_order(sketch, cls);
  StrokeGroups groups = closed_groups(sketch, cls, order, setup, profiles, taken);
  std::optional<std::size_t> last_group;
  StrokeDrawer(setup).draw(groups, [&](std::size_t first, Stroke&& stroke) {
    if (last_group != first) {
      sketch.drawn.push_back({cls, sketch.keys[order[first]], {}});
      last_group = first;
    }
    sketch.drawn.back().strokes.push_back(std::move(stroke));
  });
}

}  // namespace

void draw_inside_band(BandSketch& sketch, const DrawingSetup& setup, std::size_t profiles) {
  std::vector<char> taken(sketch.strokes.size(), 0);
  for (const StrokeClass cls : {StrokeClass::factual, StrokeClass::formulated})
    draw_class(sketch, setup, profiles, cls, taken);
  std::size_t kept = 0;
  for (std::size_t k = 0; k < sketch.strokes.size(); ++k) {
    if (taken[k]) continue;
    if (kept != k) {
      sketch.strokes[kept] = std::move(sketch.strokes[k]);
      sketch.keys[kept] = sketch.keys[k];
    }
    ++kept;
  }
  sketch.strokes.resize(kept);
  sketch.keys.resize(kept);
}

}  // namespace tsk
