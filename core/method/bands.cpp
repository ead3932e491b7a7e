#include "core/method/bands.h"

#include <algorithm>
#include <utility>

#include "core/base/byte_stream.h"
#include "core/method/profile_stages.h"

namespace tsk {
namespace {

std::size_t class_index(StrokeClass cls) {
  return cls == StrokeClass::factual ? 0 : 1;
}

// SPEC 1.7's order: chains in the order they were started, by their first profile, then front to
// back.
bool started_before(const Stroke& a, const Stroke& b) {
  const ChainCell& x = a.chain.front();
  const ChainCell& y = b.chain.front();
  return x.p != y.p ? x.p < y.p : x.i < y.i;
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
  return stream.finish_band();
}

BandStitcher::BandStitcher(const ResolvedParams& params, StrokeSink sink)
    : min_cells_(params->chain.min_cells), sink_(std::move(sink)) {
  result_.filter = params.filter();
}

void BandStitcher::keep(Stroke&& stroke) {
  StageStats& stats = result_.stats;
  stats.generalised += static_cast<std::size_t>(stroke.cells);
  ++(stroke.cls == StrokeClass::factual ? stats.factual_strokes : stats.formulated_strokes);
  if (sink_) {
    sink_(std::move(stroke));
  } else {
    result_.strokes.push_back(std::move(stroke));
  }
}

bool BandStitcher::follows(const BandSketch& band) const {
  return band.first == next_first_ && (band.first == 0 || band.in == order_);
}

void BandStitcher::add(BandSketch&& band) {
  if (!follows(band)) {
    throw Error("the band from profile " + std::to_string(band.first) +
                " does not follow: bands are stitched in order, each linked from the order of "
                "chains the band before ended with");
  }
  add_counts(band.stats, result_.stats);
  for (Stroke& stroke : band.strokes) keep(std::move(stroke));
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
  for (const StrokeCell& cell : piece.cells) builder.add(cell);
  if (piece.out < 0) {
    if (builder.cells() >= min_cells_) keep(builder.take(piece.cls));
    return;
  }
  const auto out = static_cast<std::size_t>(piece.out);
  if (out >= next_open.size() || next_open[out].live)
    throw Error("a band hands on a chain from a cell it does not order");
  next_open[out] = {std::move(builder), true};
}

SilhouetteResult BandStitcher::finish(std::size_t profiles) {
  if (next_first_ != profiles || !order_.factual.empty() || !order_.formulated.empty())
    throw Error("the bands do not reach the grid's last profile");
  std::vector<Stroke>& strokes = result_.strokes;
  // Factual first, then formulated, each in the order of the scan.
  std::sort(strokes.begin(), strokes.end(), [](const Stroke& a, const Stroke& b) {
    return a.cls != b.cls ? a.cls == StrokeClass::factual : started_before(a, b);
  });
  return std::move(result_);
}

}  // namespace tsk
