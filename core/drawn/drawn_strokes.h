// Drawn strokes (StrokeMode::drawn): the chains of a run turned into strokes a cartographer
// would publish. Joined where they visually continue, generalised after joining, smoothed within
// a tolerance of the exact chains, placed in the chosen geometry, run on at their ends if asked,
// and weighted for taper and depth (docs/DRAWN_STROKES.md).
#pragma once

#include <deque>
#include <functional>
#include <vector>

#include "core/base/geotransform.h"
#include "core/drawn/stroke_joining.h"
#include "core/method/frame.h"
#include "core/method/params.h"
#include "core/method/strokes.h"

namespace tsk {

// The fewest cells a chain needs to be drawn: a single cell has no direction to join by, and
// alone the generalisation drops it anyway.
constexpr int kLeastDrawnCells = 2;

// A step between neighbouring profiles longer than this many cells is a leap along the line of
// sight (formulated chaining looks at most 3 cells along; factual chaining follows hidden zones).
// Factual chaining links occluding cells whose hidden zones overlap, so a chain may step from one
// ridge to another far behind it: the exact stroke draws that step as a long straight line, which
// no cartographer would draw. Drawn strokes are cut there (StrokeBuilder::drawn_pieces).
constexpr double kLeapCells = 4.0;

// What drawing needs of a run: its parameters in map units.
struct DrawingSetup {
  DrawnParams drawn;
  int min_cells = 3;  // the shortest stroke drawn, raised by a scale (drawing_scale.h)
  // Pieces of fewer cells stay only where they close a gap in a line: SPEC's generalisation
  // (--min-cells), which a scale leaves as it is.
  int least_piece_cells = 3;
  double cell = 1.0;    // the view's spacing along profiles, map units
  double across = 1.0;  // the spacing of profiles, map units
  double depth = 1.0;   // the view's depth, ground units (as StrokeVertex::dist)
  Geometry geometry = Geometry::map;
  // Plan-oblique geometry: the map offset of one cell along the line of sight, and what shifts a
  // point by how many cells.
  StrokePoint cell_step{0.0, 0.0};
  double cells_per_metre = 0.0;
  double z_ref = 0.0;
  // The relief a stroke is drawn at full weight for, and below which it vanishes (0: none),
  // metres (drawing_scale.h).
  double relief_full = 0.0;
  double relief_vanishing = 0.0;
};

DrawingSetup drawing_setup(const OrientedFrame& frame, const GeoTransform& geotransform,
                           const SilhouetteParams& params, double z_ref);

// The longest step between neighbouring points of a piece, map units: where a chain is cut
// (StrokeBuilder::drawn_pieces).
double longest_step(const DrawingSetup& setup);

// How the pieces of a run join, in map units.
JoinRule join_rule(const DrawingSetup& setup);
// How many profiles apart two ends may lie and still join: the join gap across the profiles,
// and one profile more.
double join_reach_profiles(const DrawingSetup& setup);

// Groups of pieces taken to draw: their pieces one group after another.
struct StrokeGroups {
  std::vector<Stroke> pieces;
  std::vector<std::size_t> ends;    // one past each group's last piece
  std::vector<std::size_t> firsts;  // each group's first piece, by the order pieces were added
  void clear() {
    pieces.clear();
    ends.clear();
    firsts.clear();
  }
};

// Draws the strokes of one class as their chains complete, so that drawing and writing go on
// alongside the stages. Pieces (the strokes of complete chains, every one, cut where they leap,
// with their points in map geometry at sub-cell places and their vertices) come in the order of
// SPEC 1.7's scan; a group of pieces that may join is drawn once no piece still to come can join
// it. Drawn strokes come out in the order of their first pieces, each with its weights and without
// its vertices, whatever the moments draw_settled is called at.
class StrokeDrawer {
 public:
  // Takes a drawn stroke and its group, named by the group's first piece: pieces are numbered
  // from 0 in the order add() took them (those it drops not counted).
  using Out = std::function<void(std::size_t group, Stroke&& stroke)>;
  explicit StrokeDrawer(const DrawingSetup& setup);

  // The longest step between neighbouring points of a piece, map units.
  double longest_step() const;
  // A piece of a complete chain's stroke (StrokeBuilder::drawn_pieces with longest_step()).
  void add(Stroke&& piece);
  // Asks the processor for what add(piece) will look up (StrokeGrouper::prefetch).
  void prefetch(const Stroke& piece) const;
  // Takes the groups whose every end lies more than the join gap before profile `frontier`, the
  // first profile a piece still to come may reach, up to the first group that does not; after the
  // last profile, with an infinite frontier, every group left. Appends them to `into`.
  void take_settled(double frontier, StrokeGroups& into);
  // Draws groups [from_group, to_group) of those taken, in order, and hands the strokes the
  // generalisation keeps to `out`. May run on another thread than the other calls.
  void draw(StrokeGroups& groups, std::size_t from_group, std::size_t to_group,
            const Out& out) const;
  void draw(StrokeGroups& groups, const Out& out) const {
    draw(groups, 0, groups.ends.size(), out);
  }

 private:
  DrawingSetup setup_;
  JoinRule rule_;
  StrokeGrouper groups_;
  std::deque<Stroke> pending_;  // pieces from id first_pending_ on; those drawn left empty
  std::deque<bool> drawn_;
  std::vector<std::size_t> members_;  // of the group being taken, its storage reused
  std::size_t first_pending_ = 0;
};

}  // namespace tsk
