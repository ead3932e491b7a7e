#include "core/method/bands.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "core/base/byte_stream.h"
#include "core/method/profile_stages.h"

namespace tsk {
namespace {

// SPEC 1.7's order: chains in the order they were started, by their first profile, then front to
// back.
bool started_before(const Stroke& a, const Stroke& b) {
  const ChainCell& x = a.chain.front();
  const ChainCell& y = b.chain.front();
  return x.p != y.p ? x.p < y.p : x.i < y.i;
}

}  // namespace

// A chain's place in SPEC 1.7's order: by its first profile, then front to back.
std::size_t order_key(std::int32_t p, std::int32_t i) {
  return (static_cast<std::size_t>(static_cast<std::uint32_t>(p)) << 32) |
         static_cast<std::uint32_t>(i);
}

namespace {

std::pair<std::size_t, std::uint32_t> piece_key(const StrokeKey& key) {
  return {order_key(key.p, key.i), key.piece};
}

}  // namespace

BandSketch sketch_band(const DemSource& dem, const ResolvedParams& params, const BandSpec& band,
                       double z_ref, const ProgressFn& progress) {
  const OrientedFrame frame = make_frame(dem.grid, params->view.azimuth_deg);
  SilhouetteStream stream(frame, dem.geotransform, params, z_ref, band, progress);
  StripLoader loader(frame, dem.read, params->threads);
  stream_strips(
      stream, frame, band.first + band.count, strip_profiles(frame),
      [&](std::size_t first, std::size_t count, HeightGrid& heights) {
        loader.load(first, count, heights);
      },
      resolve_threads(params->threads));
  BandSketch sketch = stream.finish_band();
  // Plan-oblique strokes are drawn with the whole run's lowest height, which no band knows.
  if (params->strokes.drawn() && params->geometry == Geometry::map) {
    draw_inside_band(sketch, drawing_setup(frame, dem.geotransform, params.params(), z_ref),
                     frame.profiles);
  }
  return sketch;
}

BandStitcher::BandStitcher(const ResolvedParams& params, StrokeSink sink,
                           std::optional<DrawingSetup> drawing)
    : min_cells_(params->chain.min_cells), sink_(std::move(sink)) {
  result_.filter = params.filter();
  // Exact strokes are written alongside the stitching of the next band, a band at a time.
  if (!drawing && sink_ && resolve_threads(params->threads) > 1)
    writing_ = std::make_unique<HandOff<Stroke>>(sink_, true);
  if (!drawing) return;
  drawing_ = std::make_unique<DrawingPipeline>(
      *drawing, resolve_threads(params->threads) > 1,
      [this](StrokeClass cls, std::size_t group, Stroke&& stroke) {
        keep_drawn(cls, group, std::move(stroke));
      });
}

BandStitcher::~BandStitcher() = default;

void BandStitcher::queue_drawn_groups(std::vector<DrawnGroup>& groups) {
  if (groups.empty()) return;
  if (!drawing_) throw Error("a band drew strokes for a run of exact strokes");
  const std::lock_guard<std::mutex> lock(drawn_mutex_);
  for (DrawnGroup& group : groups) {
    std::deque<DrawnGroup>& queued = drawn_[class_index(group.cls)];
    if (!queued.empty() && !(queued.back().key < group.key))
      throw Error("a band's drawn groups are not in the order of the scan");
    queued.push_back(std::move(group));
  }
  groups.clear();
}

void BandStitcher::keep_drawn_groups(std::size_t cls, const PieceKey* key) {
  std::vector<DrawnGroup> due;
  {
    const std::lock_guard<std::mutex> lock(drawn_mutex_);
    std::deque<DrawnGroup>& drawn = drawn_[cls];
    while (!drawn.empty() && (!key || piece_key(drawn.front().key) < *key)) {
      due.push_back(std::move(drawn.front()));
      drawn.pop_front();
    }
  }
  for (DrawnGroup& group : due)
    for (Stroke& stroke : group.strokes) keep(std::move(stroke));
}

void BandStitcher::keep_drawn(StrokeClass cls, std::size_t group, Stroke&& stroke) {
  const std::size_t c = class_index(cls);
  PieceKey key;
  {
    const std::lock_guard<std::mutex> lock(drawn_mutex_);
    // Groups come in the order of their first pieces: the keys of earlier pieces are done with.
    std::deque<PieceKey>& keys = piece_keys_[c];
    if (group < first_key_[c] || group - first_key_[c] >= keys.size())
      throw Error("the drawing handed on a stroke of a piece it was not given");
    keys.erase(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(group - first_key_[c]));
    first_key_[c] = group;
    key = keys.front();
  }
  keep_drawn_groups(c, &key);
  keep(std::move(stroke));
}

void BandStitcher::hold(Stroke&& stroke, const StrokeKey& key) {
  if (!drawing_) return keep(std::move(stroke));
  held_[class_index(stroke.cls)].hold(order_key(key.p, key.i), key.piece, std::move(stroke));
}

// A chain complete: its exact stroke kept, or its drawn pieces held for the drawing.
void BandStitcher::close(StrokeBuilder& builder, StrokeClass cls) {
  if (!drawing_) {
    if (builder.cells() >= min_cells_) keep(builder.take(cls));
    return;
  }
  if (builder.cells() < kLeastDrawnCells) return;
  const ChainCell first = builder.first_cell();
  pieces_.clear();
  builder.drawn_pieces(cls, drawing_->longest_step(), pieces_);
  for (std::size_t k = 0; k < pieces_.size(); ++k)
    hold(std::move(pieces_[k]), StrokeKey{first.p, first.i, static_cast<std::uint32_t>(k)});
}

// Hands the drawing the pieces of the chains started before the oldest one still open (or to
// come), and lets it draw the groups no piece to come can join, as one run does after a profile.
void BandStitcher::hand_to_drawing() {
  for (std::size_t c = 0; c < 2; ++c) {
    const StrokeClass cls = c == 0 ? StrokeClass::factual : StrokeClass::formulated;
    std::size_t oldest = order_key(static_cast<std::int32_t>(next_first_), 0);
    for (const Open& open : open_[c]) {
      const ChainCell first = open.builder.first_cell();
      oldest = std::min(oldest, order_key(first.p, first.i));
    }
    held_[c].release_before(oldest, [&](Stroke&& piece, std::size_t chain, std::size_t k) {
      // The drawing numbers the pieces it keeps; their keys place its groups among those the
      // bands drew.
      if (piece.cells >= kLeastDrawnCells) {
        const std::lock_guard<std::mutex> lock(drawn_mutex_);
        piece_keys_[c].emplace_back(chain, static_cast<std::uint32_t>(k));
      }
      drawing_->add_piece(cls, std::move(piece));
    });
    drawing_->settle(cls, static_cast<double>(oldest >> 32));
  }
  drawing_->flush();
}

void BandStitcher::keep(Stroke&& stroke) {
  StageStats& stats = result_.stats;
  stats.generalised += static_cast<std::size_t>(stroke.cells);
  ++(stroke.cls == StrokeClass::factual ? stats.factual_strokes : stats.formulated_strokes);
  if (writing_) {
    writing_->add(std::move(stroke));
  } else if (sink_) {
    sink_(std::move(stroke));
  } else {
    result_.strokes.push_back(std::move(stroke));
  }
}

namespace {

// Each chain's place in `order` (the indices of their cells), or an empty list when `order` does
// not hold each of `cells` cells once.
std::vector<std::size_t> places(const std::vector<std::uint32_t>& order, std::size_t cells) {
  std::vector<std::size_t> place(cells, cells);
  if (order.size() != cells) return {};
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (order[k] >= cells || place[order[k]] != cells) return {};
    place[order[k]] = k;
  }
  return place;
}

// Whether `truth`, an order of the same chains as the band's guess, keeps each pair whose order
// decided a join of the band: then the band joined every cell as linked from `truth`.
bool keeps_deciding_pairs(const BandSketch& band, const BandOrders& truth, StrokeClass cls) {
  const std::vector<std::uint32_t>& guess = band.in.of(cls);
  // Both must order each of the profile's chains once.
  const std::vector<std::size_t> place = places(truth.of(cls), guess.size());
  if (place.size() != guess.size() || places(guess, guess.size()).size() != guess.size())
    return false;
  for (const OrderPair& pair : band.deciding.of(cls)) {
    if (pair.before >= place.size() || pair.after >= place.size() ||
        place[pair.before] > place[pair.after])
      return false;
  }
  return true;
}

// A band linked from a guess the true order keeps: the chains that cross into it and out of it
// come first in its order out (older than any it started), ordered there as `truth` has them.
void order_survivors(BandSketch& band, const BandOrders& truth, StrokeClass cls) {
  std::vector<std::uint32_t>& out = band.out.of(cls);
  const std::vector<std::size_t> place = places(truth.of(cls), band.in.of(cls).size());
  std::vector<std::int64_t> in_of(out.size(), -1);
  for (const BandPiece& piece : band.pieces) {
    if (piece.cls != cls || piece.in < 0 || piece.out < 0) continue;
    if (static_cast<std::size_t>(piece.out) >= out.size() ||
        static_cast<std::size_t>(piece.in) >= place.size())
      throw Error("a band's piece of a chain crossing it lies beyond its orders");
    in_of[static_cast<std::size_t>(piece.out)] = piece.in;
  }
  const auto crossing = [&](std::uint32_t k) { return k < in_of.size() && in_of[k] >= 0; };
  const auto started_here = std::find_if_not(out.begin(), out.end(), crossing);
  if (std::any_of(started_here, out.end(), crossing))
    throw Error("a band ordered a chain it started before one crossing into it");
  std::sort(out.begin(), started_here, [&](std::uint32_t a, std::uint32_t b) {
    return place[static_cast<std::size_t>(in_of[a])] < place[static_cast<std::size_t>(in_of[b])];
  });
}

}  // namespace

bool BandStitcher::follows(const BandSketch& band) const {
  if (band.first != next_first_) return false;
  if (band.first == 0 || band.in == order_) return true;
  return keeps_deciding_pairs(band, order_, StrokeClass::factual) &&
         keeps_deciding_pairs(band, order_, StrokeClass::formulated);
}

void BandStitcher::add(BandSketch&& band) {
  if (!follows(band)) {
    throw Error("the band from profile " + std::to_string(band.first) +
                " does not follow: bands are stitched in order, each linked from the order of "
                "chains the band before ended with");
  }
  if (band.keys.size() != band.strokes.size())
    throw Error("a band's strokes and their places in the order do not match");
  if (band.first > 0 && band.in != order_) {
    for (const StrokeClass cls : {StrokeClass::factual, StrokeClass::formulated})
      order_survivors(band, order_, cls);
  }
  add_counts(band.stats, result_.stats);
  queue_drawn_groups(band.drawn);
  for (std::size_t k = 0; k < band.strokes.size(); ++k)
    hold(std::move(band.strokes[k]), band.keys[k]);
  std::vector<Open> next[2];
  next[0].resize(band.out.factual.size());
  next[1].resize(band.out.formulated.size());
  for (BandPiece& piece : band.pieces) join(piece, next[class_index(piece.cls)]);
  for (std::size_t c = 0; c < 2; ++c) {
    for (const Open& open : open_[c])
      if (open.live) throw Error("a band lost a chain that the band before handed on");
    for (const Open& open : next[c])
      if (!open.live) throw Error("a band handed on an order of chains it did not hand on");
    open_[c] = std::move(next[c]);
  }
  order_ = std::move(band.out);
  next_first_ = band.first + band.count;
  if (drawing_) hand_to_drawing();
  if (writing_) writing_->flush();
}

void BandStitcher::add(BandSketch&& band, const SketchAgain& again) {
  if (!follows(band)) band = again(band.first, band.count, order_);
  add(std::move(band));
}

void BandStitcher::join(BandPiece& piece, std::vector<Open>& next_open) {
  std::vector<Open>& open = open_[class_index(piece.cls)];
  StrokeBuilder builder;
  if (piece.in >= 0) {
    const auto in = static_cast<std::size_t>(piece.in);
    if (in >= open.size() || !open[in].live)
      throw Error("a band's piece of a chain joins no chain of the band before");
    builder = std::move(open[in].builder);
    open[in].live = false;
  }
  // Cell after cell, as one run builds the stroke: the same sums in the same order.
  for (const StrokeCell& cell : piece.cells) builder.add(cell, drawing_ != nullptr);
  if (piece.out < 0) return close(builder, piece.cls);
  const auto out = static_cast<std::size_t>(piece.out);
  if (out >= next_open.size() || next_open[out].live)
    throw Error("a band hands on a chain from a cell it does not order");
  next_open[out] = {std::move(builder), true};
}

SilhouetteResult BandStitcher::finish(std::size_t profiles) {
  if (next_first_ != profiles || !order_.factual.empty() || !order_.formulated.empty())
    throw Error("the bands do not reach the grid's last profile");
  // Exact strokes come in the bands' order; drawn ones are drawn in SPEC 1.7's.
  if (drawing_) {
    hand_to_drawing();  // every piece, as no chain is open or to come
    for (const StrokeClass cls : {StrokeClass::factual, StrokeClass::formulated})
      drawing_->settle(cls, std::numeric_limits<double>::infinity());
    drawing_->flush();
    drawing_->finish();
    for (std::size_t c = 0; c < 2; ++c) keep_drawn_groups(c, nullptr);
  }
  if (writing_) writing_->finish();
  std::vector<Stroke>& strokes = result_.strokes;
  // Factual first, then formulated, each in the order of the scan.
  if (drawing_) {
    // Drawn in one run's order already: factual first, as one run gives them.
    std::stable_partition(strokes.begin(), strokes.end(),
                          [](const Stroke& s) { return s.cls == StrokeClass::factual; });
  } else {
    std::sort(strokes.begin(), strokes.end(), [](const Stroke& a, const Stroke& b) {
      return a.cls != b.cls ? a.cls == StrokeClass::factual : started_before(a, b);
    });
  }
  return std::move(result_);
}

}  // namespace tsk
