// Drawing inside a band (bands.h): the groups of drawn pieces that no other band can join are
// drawn by the band itself, so that a cluster's client draws only what lies near the bands' edges.
#include <algorithm>
#include <cmath>
#include <cstdint>
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

// Groups the pieces `order` names as the drawing does; returns, by each group's first piece,
// whether a piece of another band may join it.
std::vector<char> group_pieces(const BandSketch& sketch, StrokeClass cls,
                               const std::vector<std::size_t>& order, const DrawingSetup& setup,
                               std::size_t profiles, StrokeGrouper& grouper) {
  // An end on profile p may meet an end of another band's profile only this many profiles away.
  const double reach = join_reach_profiles(setup);
  const bool before = sketch.first > 0, after = sketch.first + sketch.count < profiles;
  const auto near_edge = [&](std::int32_t p) {
    const double q = static_cast<double>(p);
    return (before && q - (static_cast<double>(sketch.first) - 1.0) <= reach) ||
           (after && static_cast<double>(sketch.first + sketch.count) - q <= reach);
  };
  const CrossingCells crossing(sketch.pieces, cls, join_rule(setup).gap);
  std::vector<char> open(order.size(), 0);
  for (std::size_t n = 0; n < order.size(); ++n) {
    const Stroke& piece = sketch.strokes[order[n]];
    grouper.add(piece);
    open[n] = near_edge(piece.chain.front().p) || near_edge(piece.chain.back().p) ||
              crossing.near(piece.points.front()) || crossing.near(piece.points.back());
  }
  std::vector<char> group_open(order.size(), 0);
  for (std::size_t n = 0; n < order.size(); ++n)
    if (open[n]) group_open[grouper.group_of(n)] = 1;
  return group_open;
}

// Draws the groups of class `cls` that no other band can join into sketch.drawn, marking their
// pieces (and those the drawing drops) in `taken`.
void draw_class(BandSketch& sketch, const DrawingSetup& setup, std::size_t profiles,
                StrokeClass cls, std::vector<char>& taken) {
  for (std::size_t k = 0; k < sketch.strokes.size(); ++k)
    if (sketch.strokes[k].cls == cls && sketch.strokes[k].cells < kLeastDrawnCells) taken[k] = 1;
  const std::vector<std::size_t> order = pieces_in_order(sketch, cls);
  const JoinRule rule = join_rule(setup);
  // Without a gap nothing joins: every piece is a group of its own that no band can reach.
  const bool joins = rule.gap > 0.0;
  std::optional<StrokeGrouper> grouper;
  std::vector<char> open(order.size(), 0);
  if (joins) open = group_pieces(sketch, cls, order, setup, profiles, grouper.emplace(rule));
  StrokeGroups groups;
  std::vector<std::size_t> members;
  for (std::size_t n = 0; n < order.size(); ++n) {
    if (joins) {
      if (grouper->group_of(n) != n || open[n]) continue;
      grouper->take_group(n, members);
    } else {
      members.assign(1, n);
    }
    for (const std::size_t m : members) {
      groups.pieces.push_back(std::move(sketch.strokes[order[m]]));
      taken[order[m]] = 1;
    }
    groups.ends.push_back(groups.pieces.size());
    groups.firsts.push_back(n);
  }
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
