// A run split into bands of profiles, for machines that each sketch a band (the Python package's
// Dask runs): every band is sketched on its own, then the bands are stitched, in order, into the
// strokes of the whole run, exactly as one run makes them (exact strokes).
//
// SPEC 1.7 links chains profile by profile, left to right, the older chains choosing first, so a
// band's linking depends on the order of the chains open where it starts. A band guesses it by
// linking `halo` profiles before its first from nothing; the stitcher knows the true order from
// the band before, and a band whose guess was wrong is sketched again from the true order. The
// chains that run across a band's edges leave it as pieces, their cells kept, which the stitcher
// joins, building each stroke cell by cell as one run does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/drawn/drawing_pipeline.h"
#include "core/method/scan_order.h"
#include "core/method/silhouettes.h"

namespace tsk {

// A list for each class of strokes.
template <typename T>
struct ByClass {
  std::vector<T> factual, formulated;
  std::vector<T>& of(StrokeClass cls) { return cls == StrokeClass::factual ? factual : formulated; }
  const std::vector<T>& of(StrokeClass cls) const {
    return cls == StrokeClass::factual ? factual : formulated;
  }
  bool operator==(const ByClass& o) const {
    return factual == o.factual && formulated == o.formulated;
  }
  bool operator!=(const ByClass& o) const { return !(*this == o); }
};

// The chains open after a profile, oldest first, as the indices of their cells among the
// profile's chain candidates: one order per class.
using BandOrders = ByClass<std::uint32_t>;

struct BandSpec {
  std::size_t first = 0, count = 0;  // the profiles the band owns: [first, first + count)
  // The order of the chains open at profile first - 1, when known (from the band before); else
  // the band guesses it by linking `halo` profiles before its first (at least one).
  std::optional<BandOrders> order;
  std::size_t halo = 64;
};

// A chain's cells in a band, when it runs in from the band before or on into the next.
struct BandPiece {
  StrokeClass cls = StrokeClass::factual;
  std::int64_t in = -1;   // its cell's index among the candidates of profile first - 1, or -1
  std::int64_t out = -1;  // its cell's index among the candidates of the band's last profile
  std::vector<StrokeCell> cells;  // its cells in the band, in order (none when it ends at first)
};

// Where a stroke of a band stands in SPEC 1.7's order: the first cell of its chain, and for a
// drawn stroke's piece, its place among the chain's pieces.
struct StrokeKey {
  std::int32_t p = 0, i = 0;
  std::uint32_t piece = 0;
  // SPEC 1.7's order: the chain's first cell (profile, then front to back), then the piece.
  bool operator<(const StrokeKey& o) const {
    return std::tie(p, i, piece) < std::tie(o.p, o.i, o.piece);
  }
};

// A group of drawn pieces that no piece of another band can join, drawn by its band: its strokes
// (none when the generalisation drops them all), placed in the run's order by the key of its
// first piece.
struct DrawnGroup {
  StrokeClass cls = StrokeClass::factual;
  StrokeKey key;
  std::vector<Stroke> strokes;
};

struct BandSketch {
  std::size_t first = 0, count = 0;
  StageStats stats;  // the cells of the band's own profiles (no strokes counted)
  // The chains wholly in the band: exact strokes at least min_cells long, or the pieces of drawn
  // ones (StrokeBuilder::drawn_pieces), to be drawn by the stitcher; with their keys.
  std::vector<Stroke> strokes;
  std::vector<StrokeKey> keys;
  // Drawn strokes in map geometry: the groups of pieces far enough from the band's edges and from
  // the chains that cross them, drawn here (their pieces are not among `strokes`); each class in
  // the order of its keys.
  std::vector<DrawnGroup> drawn;
  std::vector<BandPiece> pieces;
  BandOrders in;   // the order at first - 1 the band linked from, given or guessed
  BandOrders out;  // the order after its last profile (none at the grid's end)
  // A guessed `in`: the pairs of its chains whose order decided a join in the band
  // (ChainLinker::deciding_pairs). A true order that keeps each pair links the band alike.
  ByClass<OrderPair> deciding;
  FilterReport filter;
};

// Sketches one band of the run of `params` on the DEM read window by window: what a machine of a
// cluster does. z_ref as sketch_silhouettes finds it (plan-oblique geometry). Throws Error on a
// band beyond the grid, and what `read` throws; Cancelled when `progress` says stop.
BandSketch sketch_band(const DemSource& dem, const ResolvedParams& params, const BandSpec& band,
                       double z_ref = 0.0, const ProgressFn& progress = {});

// Draws the groups of a band's drawn pieces (sketch.strokes) that no piece of another band can
// join: every end of their pieces lies farther than the join gap from the band's edges (those
// inside the grid) and from every cell of the chains crossing them. Such a group is drawn as one
// run draws it, from the same pieces in the same order; it goes to sketch.drawn, and its pieces
// leave sketch.strokes. `setup` is the run's (drawing_setup), `profiles` the grid's.
void draw_inside_band(BandSketch& sketch, const DrawingSetup& setup, std::size_t profiles);

// Joins bands, given in order, into the strokes of the whole run.
class BandStitcher {
 public:
  // With a sink, each stroke goes to it as soon as its band is added (exact strokes: the bands'
  // order, not SPEC 1.7's), and the result of finish() holds none. Drawn strokes are drawn here,
  // in SPEC 1.7's order as one run draws them, with `drawing` (drawing_setup of the run).
  BandStitcher(const ResolvedParams& params, StrokeSink sink = {},
               std::optional<DrawingSetup> drawing = std::nullopt);
  ~BandStitcher();
  // Whether `band` is the next one and linked as from the true order: from that order, or from a
  // guess that keeps every pair of chains whose order decided a join (else it must be sketched
  // again from the true order: add() with `again`).
  bool follows(const BandSketch& band) const;
  // The order of the chains open where the next band starts.
  const BandOrders& order() const { return order_; }
  // Throws Error unless it follows.
  void add(BandSketch&& band);
  // The band sketched again from the true order at its first profile.
  using SketchAgain =
      std::function<BandSketch(std::size_t first, std::size_t count, const BandOrders& order)>;
  // Adds `band`, or, when its guess of the order was wrong, the band `again` sketches.
  void add(BandSketch&& band, const SketchAgain& again);
  // After the band holding the grid's last profile: the strokes in SPEC 1.7's order (factual,
  // then formulated), and the statistics, as one run gives them. `profiles`: the grid's.
  SilhouetteResult finish(std::size_t profiles);

 private:
  // A piece's place in SPEC 1.7's order: its chain's (order_key), then its own among the chain's.
  using PieceKey = std::pair<std::size_t, std::uint32_t>;
  // A chain going on into the next band: its stroke so far.
  struct Open {
    StrokeBuilder builder;
    bool live = false;
  };
  void join(BandPiece& piece, std::vector<Open>& next_open);
  void close(StrokeBuilder& builder, StrokeClass cls);
  void hold(Stroke&& stroke, const StrokeKey& key);
  void hand_to_drawing();
  void keep(Stroke&& stroke);
  // Keeps a stroke the drawing hands on, after the groups drawn by their bands that come before
  // its group in the run's order.
  void keep_drawn(StrokeClass cls, std::size_t group, Stroke&& stroke);
  // Queues the groups a band drew, to be kept in their places in the run's order.
  void queue_drawn_groups(std::vector<DrawnGroup>& groups);
  // Keeps the groups drawn by their bands whose first piece comes before `key` (all of them
  // without one).
  void keep_drawn_groups(std::size_t cls, const PieceKey* key);

  int min_cells_;
  StrokeSink sink_;
  std::size_t next_first_ = 0;
  BandOrders order_;
  std::vector<Open> open_[2];  // by class, indexed by the cell's index in the last profile
  SilhouetteResult result_;
  // Drawn strokes: the pieces held until every chain started before theirs is complete, then
  // drawn in that order, as one run draws them.
  ScanOrder held_[2];
  std::vector<Stroke> pieces_;
  // By class: the groups drawn by their bands, in order, and the keys of the pieces given to the
  // drawing from piece `first_key_` on, which the drawing's thread reads.
  std::mutex drawn_mutex_;
  std::deque<DrawnGroup> drawn_[2];
  std::deque<PieceKey> piece_keys_[2];
  std::size_t first_key_[2] = {0, 0};
  // Declared last: stopped before what they deliver to goes. Exact strokes with a sink are
  // written on a thread of their own.
  std::unique_ptr<HandOff<Stroke>> writing_;
  std::unique_ptr<DrawingPipeline> drawing_;
};

// A band sketch as bytes and back, for a machine to hand it to another: an exact stroke's chain,
// and that of a stroke its band has drawn, keep only their first cell, which is all the stitcher
// reads of them (a drawn stroke's piece keeps its whole chain, which the drawing joins). Throws
// Error on bytes that are not one.
std::string band_bytes(const BandSketch& band);
BandSketch band_from_bytes(std::string_view bytes);
std::string orders_bytes(const BandOrders& orders);
BandOrders orders_from_bytes(const std::string& bytes);
// A filter's report as bytes, field by field so that no padding goes out, and back.
std::string filter_report_bytes(const FilterReport& report);
FilterReport filter_report_from_bytes(const std::string& bytes);

}  // namespace tsk
