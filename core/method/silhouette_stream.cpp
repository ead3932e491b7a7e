// SilhouetteStream: the method strip by strip, each profile's stages while its cells are in
// cache, the chains linked in the order of the scan as the next profiles are classified.
#include <algorithm>
#include <limits>
#include <memory>
#include <mutex>
#include <utility>

#include "core/base/errors.h"
#include "core/base/prefetch.h"
#include "core/base/stage_timing.h"
#include "core/drawn/drawing_pipeline.h"
#include "core/drawn/drawn_strokes.h"
#include "core/method/bands.h"
#include "core/method/chain_order.h"
#include "core/method/chaining.h"
#include "core/method/profile_stages.h"
#include "core/method/silhouettes.h"

namespace tsk {
namespace {

// Profiles to a batch: about a million cells, at least 128 profiles. Short profiles come in more
// to a batch, as every batch costs a thread start or two whatever its size. (Two batches' chain
// cells are held at a time: 256 profiles of 8000 cells held 115 MB at the default run's peak.)
std::size_t batch_profiles(std::size_t length) {
  return std::clamp<std::size_t>((std::size_t{1} << 20) / std::max<std::size_t>(1, length), 128,
                                 16384);
}

// How many cells ahead the linking fetches the builder of a cell's chain (and half as many, the
// end of its cells).
constexpr std::size_t kBuildersAhead = 6;

// Whether drawn strokes are drawn, and handed on, on threads of their own.
bool draws_alongside(const SilhouetteParams& p) {
  return p.strokes.drawn() && resolve_threads(p.threads) > 1;
}

}  // namespace

// The linking of a run: chains linked profile by profile (SPEC 1.7), their strokes kept in the
// order of the scan and handed on, or to the drawing for drawn strokes.
struct SilhouetteStream::State {
  // One class of strokes: its linker, the strokes of its open chains by slot, and its complete
  // strokes held until every chain started before theirs is complete too.
  struct Strokes {
    Strokes(bool factual, int window)
        : linker(factual, window), cls(factual ? StrokeClass::factual : StrokeClass::formulated) {}
    ChainLinker linker;
    StrokeClass cls;
    std::vector<StrokeBuilder> open;
    ChainOrder order;
    std::vector<Stroke> pieces;        // of the drawn chain closing, its storage reused
    std::vector<Stroke> handed_on;     // without a sink
    std::size_t count = 0, cells = 0;  // of the strokes handed on
  };

  OrientedFrame frame;
  GeoTransform geotransform;
  SilhouetteParams params;
  double z_ref;
  ProgressFn progress;
  StrokeSink sink;
  std::size_t next_profile = 0;
  std::size_t next_linked = 0;  // the next profile to link
  Strokes factual{true, 0}, formulated;
  CellFlags flags;  // the current strip's classification, its memory reused by the next strip
  SilhouetteResult result;
  // A band of the run (bands.h): linked from `link_from`, owning [owned_first, owned_end).
  struct BandLinks {
    std::vector<std::int64_t> in;                // by slot: its cell's index at owned_first - 1
    std::vector<std::vector<StrokeCell>> cells;  // by slot: its cells in the band
  };
  struct Band {
    std::size_t link_from = 0, owned_first = 0, owned_end = 0;
    double longest_step = 0.0;  // drawn strokes: where their chains are cut (> 0)
    std::optional<BandOrders> given;
    BandLinks factual, formulated;
    BandSketch sketch;
  };
  std::optional<Band> band;
  // Declared last, stopped before what they deliver to goes. Exact strokes of a whole run are
  // written alongside the linking, a batch at a time (writing took longer than the linking).
  std::unique_ptr<HandOff<Stroke>> writing;
  std::unique_ptr<DrawingPipeline> drawing;  // drawn strokes only

  State(const OrientedFrame& f, const GeoTransform& gt, const SilhouetteParams& p, double z,
        const ProgressFn& pr, StrokeSink sk)
      : frame(f),
        geotransform(gt),
        params(p),
        z_ref(z),
        progress(pr),
        sink(std::move(sk)),
        formulated(false, p.chain.window) {}

  // A whole run's strokes are drawn, or written to the sink, alongside the linking (a band leaves
  // its pieces to the stitcher).
  void start_handing_on() {
    if (!params.strokes.drawn()) {
      if (sink && resolve_threads(params.threads) > 1)
        writing = std::make_unique<HandOff<Stroke>>(sink, true);
      return;
    }
    drawing = std::make_unique<DrawingPipeline>(
        drawing_setup(frame, geotransform, params, z_ref), draws_alongside(params),
        [this](StrokeClass cls, std::size_t, Stroke&& stroke) {
          deliver(cls == StrokeClass::factual ? factual : formulated, std::move(stroke));
        });
  }

  // Checks that a strip of `count` profiles from `first` follows the last one and matches the
  // frame; returns how many neighbour profiles it holds before its first (0 or 1).
  std::size_t accept_strip(const HeightGrid& z, std::size_t first, std::size_t count) {
    const std::size_t before = first > 0 ? 1 : 0;
    const std::size_t after = first + count < frame.profiles ? 1 : 0;
    if (first != next_profile || count == 0 || z.rows() != before + count + after ||
        z.cols() != frame.length) {
      throw Error("strip of profiles does not follow the previous one or does not match the frame");
    }
    next_profile = first + count;
    return before;
  }

  // Tells `progress` that `done` profiles are done; throws Cancelled when it says stop.
  void report_progress(std::size_t done) const {
    const std::size_t from = band ? band->link_from : 0;
    const std::size_t to = band ? band->owned_end : frame.profiles;
    tell_progress(progress, static_cast<double>(done - from) / static_cast<double>(to - from));
  }

  // Links the chain candidates of a batch of profiles, in order (SPEC 1.7).
  void link(const std::vector<ProfileChainCells>& batch) {
    for (const ProfileChainCells& c : batch) {
      if (band) {
        link_band(factual, band->factual, c.factual, c.factual_cells);
        link_band(formulated, band->formulated, c.formulated, c.formulated_cells);
        ++next_linked;
        continue;
      }
      link(factual, c.factual, c.factual_cells);
      link(formulated, c.formulated, c.formulated_cells);
      ++next_linked;
      // Profile by profile, so that the two classes interleave alike whatever the batches.
      if (drawing) {
        take_settled(factual);
        take_settled(formulated);
        drawing->flush_when_full();
      }
    }
    if (drawing) drawing->flush();
    if (writing) writing->flush();
  }

  // Adds the cells of a profile's candidates to the strokes of their chains, finishes the closed
  // chains and hands on the strokes no open chain precedes.
  void link(Strokes& strokes, const ProfileCandidates& candidates,
            const std::vector<StrokeCell>& cells) {
    const auto& joined = strokes.linker.add_profile(candidates);
    std::vector<StrokeBuilder>& open = strokes.open;
    if (open.size() < strokes.linker.slot_count()) open.resize(strokes.linker.slot_count());
    const bool drawn = drawing != nullptr;
    for (std::size_t k = 0; k < joined.size(); ++k) {
      // Each cell goes to another of about a thousand open chains, whose builder is seldom in the
      // cache: it is fetched a few cells ahead with the cell's record (made on a stage thread),
      // and then the end of its cells.
      if (k + 2 * kBuildersAhead < joined.size()) {
        __builtin_prefetch(&open[joined[k + 2 * kBuildersAhead].slot]);
        prefetch_record(cells[k + 2 * kBuildersAhead]);
      }
      if (k + kBuildersAhead < joined.size()) open[joined[k + kBuildersAhead].slot].prefetch(drawn);
      open[joined[k].slot].add(cells[k], drawn);
    }
    close(strokes, strokes.linker.closed());
    hand_on(strokes, strokes.linker.oldest_open());
  }

  // Asks the drawing for the groups of drawn strokes that no chain still open or to come can
  // join (after the last profile, all of them), to be drawn in that order.
  void take_settled(Strokes& strokes, bool last = false) {
    const ChainRef* oldest = strokes.linker.oldest_open_chain();
    const double frontier = last     ? std::numeric_limits<double>::infinity()
                            : oldest ? strokes.open[oldest->slot].first_profile()
                                     : static_cast<double>(next_linked);
    drawing->settle(strokes.cls, frontier);
  }

  // Keeps the strokes of closed chains long enough to draw (every one the drawing can use for
  // drawn strokes, which are generalised after joining); their slots' storage is reused.
  void close(Strokes& strokes, const std::vector<ChainRef>& chains) {
    const int min_cells = drawing ? kLeastDrawnCells : params.chain.min_cells;
    // A chain's first cells were added long before it closed: the builders of the chains closed
    // are fetched first, then each one's cells while the one before is cut into pieces.
    for (const ChainRef& chain : chains) __builtin_prefetch(&strokes.open[chain.slot]);
    for (std::size_t c = 0; c < chains.size(); ++c) {
      const ChainRef& chain = chains[c];
      if (c + 1 < chains.size())
        strokes.open[chains[c + 1].slot].prefetch_cells(drawing != nullptr);
      StrokeBuilder& builder = strokes.open[chain.slot];
      if (builder.cells() >= min_cells) {
        // Copies sized to fit: the builder keeps its storage for the slot's next chain (taking
        // its vectors left them to grow anew, allocation after allocation).
        if (drawing) {
          strokes.pieces.clear();
          builder.drawn_pieces(strokes.cls, drawing->longest_step(), strokes.pieces);
          for (std::size_t k = 0; k < strokes.pieces.size(); ++k)
            strokes.order.hold(chain.id, k, std::move(strokes.pieces[k]));
        } else {
          strokes.order.hold(chain.id, 0, builder.stroke(strokes.cls));
        }
      }
      builder.clear();
    }
  }

  // Hands on the held strokes of chains started before chain `id`, oldest first: to the drawing
  // for drawn strokes.
  void hand_on(Strokes& strokes, std::size_t id) {
    strokes.order.release_before(id, [&](Stroke&& stroke) {
      if (drawing) {
        drawing->add_piece(strokes.cls, std::move(stroke));
      } else {
        deliver(strokes, std::move(stroke));
      }
    });
  }

  // After the last profile: hands the drawing the strokes still held a run of chains at a time,
  // each run followed by the settling of the groups that no piece of a later chain can reach, so
  // that grouping, drawing and writing go on alongside each other to the end. Handed on at once,
  // the pieces still held (24 000 on the 8000^2 benchmark's defaults) went through the three one
  // after the other. The strokes drawn are the same, in the same order: the drawing's order does
  // not depend on when groups settle.
  void hand_on_last(Strokes& strokes) {
    constexpr std::size_t kChainsPerRun = 512;
    strokes.order.release_all_in_runs(
        kChainsPerRun, [&](Stroke&& piece) { drawing->add_piece(strokes.cls, std::move(piece)); },
        [&](double frontier) {
          drawing->settle(strokes.cls, frontier);
          drawing->flush();
        });
    take_settled(strokes, true);
  }

  // Links profile next_linked of a band: before its first, only to learn the order of the chains
  // open where it starts; from its first on, keeping each chain's cells.
  void link_band(Strokes& strokes, BandLinks& links, const ProfileCandidates& candidates,
                 const std::vector<StrokeCell>& cells) {
    const std::size_t p = next_linked;
    ChainLinker& linker = strokes.linker;
    const std::vector<ChainRef>* joined = nullptr;
    if (p + 1 == band->owned_first && band->given) {
      linker.start_from(candidates, band->given->of(strokes.cls));
    } else {
      joined = &linker.add_profile(candidates);
    }
    links.in.resize(linker.slot_count(), -1);
    links.cells.resize(linker.slot_count());
    if (p + 1 == band->owned_first) {
      std::vector<std::uint32_t>& order = band->sketch.in.of(strokes.cls);
      for (const ChainLinker::Open& o : linker.open()) {
        links.in[o.chain.slot] = static_cast<std::int64_t>(o.k);
        order.push_back(static_cast<std::uint32_t>(o.k));
      }
      // A guessed order may differ from the true one: the stitcher checks the pairs it decides.
      if (!band->given) linker.record_deciding_pairs();
    }
    if (p < band->owned_first) return;
    for (std::size_t k = 0; k < joined->size(); ++k)
      links.cells[(*joined)[k].slot].push_back(cells[k]);
    for (const ChainRef& chain : linker.closed()) finish_piece(strokes.cls, links, chain.slot, -1);
  }

  // A chain of a band closed (out < 0) or going on into the next band from cell `out` of its last
  // profile: a stroke when it lies wholly in the band, else a piece for the stitcher.
  void finish_piece(StrokeClass cls, BandLinks& links, std::uint32_t slot, std::int64_t out) {
    std::vector<StrokeCell> cells = std::move(links.cells[slot]);
    links.cells[slot].clear();
    const std::int64_t in = links.in[slot];
    links.in[slot] = -1;
    if (in >= 0 || out >= 0) {
      band->sketch.pieces.push_back({cls, in, out, std::move(cells)});
      return;
    }
    const bool drawn = band->longest_step > 0.0;
    if (static_cast<int>(cells.size()) < (drawn ? kLeastDrawnCells : params.chain.min_cells))
      return;
    StrokeBuilder builder;
    for (const StrokeCell& cell : cells) builder.add(cell, drawn);
    const ChainCell first = cells.front().cell;
    if (!drawn) {
      band->sketch.strokes.push_back(builder.take(cls));
      band->sketch.keys.push_back({first.p, first.i, 0});
      return;
    }
    // The pieces of a drawn stroke, drawn by the stitcher in the order of the scan.
    std::vector<Stroke> pieces;
    builder.drawn_pieces(cls, band->longest_step, pieces);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      band->sketch.strokes.push_back(std::move(pieces[k]));
      band->sketch.keys.push_back({first.p, first.i, static_cast<std::uint32_t>(k)});
    }
  }

  // At the band's end: its open chains go on into the next band, in their order, or close at the
  // grid's end.
  void finish_band(Strokes& strokes, BandLinks& links) {
    ChainLinker& linker = strokes.linker;
    if (!band->given) band->sketch.deciding.of(strokes.cls) = linker.deciding_pairs();
    if (band->owned_end == frame.profiles) {
      for (const ChainRef& chain : linker.close_all())
        finish_piece(strokes.cls, links, chain.slot, -1);
      return;
    }
    std::vector<std::uint32_t>& order = band->sketch.out.of(strokes.cls);
    for (const ChainLinker::Open& o : linker.open()) {
      order.push_back(static_cast<std::uint32_t>(o.k));
      finish_piece(strokes.cls, links, o.chain.slot, static_cast<std::int64_t>(o.k));
    }
  }

  void deliver(Strokes& strokes, Stroke&& stroke) {
    ++strokes.count;
    strokes.cells += static_cast<std::size_t>(stroke.cells);
    if (writing) {
      writing->add(std::move(stroke));
    } else if (sink) {
      sink(std::move(stroke));
    } else {
      strokes.handed_on.push_back(std::move(stroke));
    }
  }
};

SilhouetteStream::SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                                   const ResolvedParams& params, double z_ref,
                                   const ProgressFn& progress, StrokeSink sink)
    : state_(std::make_unique<State>(frame, geotransform, params.params(), z_ref, progress,
                                     std::move(sink))) {
  state_->result.filter = params.filter();
  state_->start_handing_on();
}

SilhouetteStream::SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                                   const ResolvedParams& params, double z_ref, const BandSpec& band,
                                   const ProgressFn& progress)
    : state_(std::make_unique<State>(frame, geotransform, params.params(), z_ref, progress,
                                     StrokeSink())) {
  state_->result.filter = params.filter();
  if (band.count == 0 || band.first > frame.profiles || band.count > frame.profiles - band.first)
    throw Error("the band of profiles " + std::to_string(band.first) + " + " +
                std::to_string(band.count) + " does not lie in the grid's " +
                std::to_string(frame.profiles));
  State::Band b;
  b.owned_first = band.first;
  b.owned_end = band.first + band.count;
  b.given = band.order;
  const std::size_t halo = band.order ? 1 : std::max<std::size_t>(1, band.halo);
  b.link_from = band.first - std::min(band.first, halo);
  b.sketch.first = band.first;
  b.sketch.count = band.count;
  b.sketch.filter = params.filter();
  // A band cuts its drawn chains into pieces where they leap; the stitcher draws them, in order.
  if (params->strokes.drawn())
    b.longest_step = longest_step(drawing_setup(frame, geotransform, params.params(), z_ref));
  state_->band = std::move(b);
  state_->next_profile = state_->next_linked = state_->band->link_from;
}

std::size_t SilhouetteStream::next_profile() const {
  return state_->next_profile;
}

BandSketch SilhouetteStream::finish_band() {
  State& st = *state_;
  if (!st.band || st.next_profile != st.band->owned_end)
    throw Error("not every profile of the band was delivered");
  st.finish_band(st.factual, st.band->factual);
  st.finish_band(st.formulated, st.band->formulated);
  BandSketch sketch = std::move(st.band->sketch);
  sketch.stats = st.result.stats;
  tell_progress(st.progress, 1.0);
  return sketch;
}

SilhouetteStream::~SilhouetteStream() = default;

void SilhouetteStream::add_strip(const HeightGrid& z, std::size_t first, std::size_t count,
                                 bool keep_flags) {
  State& st = *state_;
  const std::size_t before = st.accept_strip(z, first, count);
  st.flags.reshape(z.rows(), z.cols(), kUnset);  // rows of the neighbours stay unused
  const StrokeContext context{
      z,
      st.flags,
      st.frame,
      st.params.view,
      st.geotransform,
      st.params.geometry,
      st.params.subcell,
      st.params.strokes.drawn(),
      CandidateBounds(st.params.view, st.frame.d, st.params.height_tolerance),
      st.z_ref,
      first - before};
  const unsigned threads = resolve_threads(st.params.threads);
  const std::size_t batch = batch_profiles(st.frame.length);
  std::mutex merge;
  StageTimings seconds;  // time of each stage summed over the threads
  // Batches of profiles are classified and their chain candidates collected in parallel...
  auto collect = [&](std::size_t b0, std::vector<ProfileChainCells>& cells) {
    cells.resize(std::min(batch, count - b0));  // every entry refilled, storage reused
    parallel_for(cells.size(), threads, [&](std::size_t lo, std::size_t hi) {
      StageTimings sampled;
      StageStats counts;
      for (std::size_t k = lo; k < hi; ++k) {
        const std::size_t row = before + b0 + k, p = first + b0 + k;
        StageClock clock{p % kTimedEvery == 0, sampled};
        std::uint8_t* f = st.flags.row(row);
        const CellRange range = classify_profile(z, row, p, f, st.frame, st.params, clock);
        clock.time(&StageTimings::chaining, [&] {
          if (!st.band || p >= st.band->owned_first)
            count_profile(f + range.begin, range.size(), counts);
          cells[k].collect(context, f, p, range);
        });
      }
      std::lock_guard<std::mutex> lock(merge);
      add_sampled_times(sampled, seconds);
      add_counts(counts, st.result.stats);
    });
  };
  // ... then linked in order on a thread of their own while the next batch is collected.
  auto link = [&](const std::vector<ProfileChainCells>& cells) {
    const auto start = Clock::now();
    st.link(cells);
    std::lock_guard<std::mutex> lock(merge);
    seconds.chaining += seconds_since(start);
  };
  const auto start = Clock::now();
  pipeline_batches<std::vector<ProfileChainCells>>(
      count, batch, threads > 1, collect, link,
      [&](std::size_t done) { st.report_progress(first + done); });
  share_out(seconds, seconds_since(start), st.result.timings);
  if (keep_flags) {
    st.result.flags = std::move(st.flags);
    st.flags = CellFlags();
  }
}

SilhouetteResult SilhouetteStream::finish() {
  State& st = *state_;
  if (st.band) throw Error("a band of a run ends with finish_band");
  if (st.next_profile != st.frame.profiles) throw Error("not every profile was delivered");
  const auto start = Clock::now();
  for (State::Strokes* strokes : {&st.factual, &st.formulated}) {
    st.close(*strokes, strokes->linker.close_all());
    if (st.drawing) {
      st.hand_on_last(*strokes);
    } else {
      st.hand_on(*strokes, std::numeric_limits<std::size_t>::max());
    }
  }
  if (st.drawing) {
    st.drawing->flush();
    st.drawing->finish();
  }
  if (st.writing) st.writing->finish();
  SilhouetteResult& result = st.result;
  StageStats& stats = result.stats;
  stats.generalised = st.factual.cells + st.formulated.cells;
  stats.factual_strokes = st.factual.count;
  stats.formulated_strokes = st.formulated.count;
  result.z_ref = st.z_ref;
  // Without a sink: factual strokes first, then formulated, each in the order of the scan.
  result.strokes = std::move(st.factual.handed_on);
  result.strokes.reserve(result.strokes.size() + st.formulated.handed_on.size());
  for (Stroke& stroke : st.formulated.handed_on) result.strokes.push_back(std::move(stroke));
  result.timings.strokes += seconds_since(start);
  tell_progress(st.progress, 1.0);
  return std::move(result);
}

}  // namespace tsk
