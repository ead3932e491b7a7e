#include "silhouettes.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <future>
#include <limits>
#include <mutex>

#include "candidates.h"
#include "chaining.h"
#include "profile_plot.h"
#include "slope_filter.h"
#include "thinning.h"
#include "visibility.h"

namespace tsk {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Adds the classification counts of rows [first_row, first_row + rows) to `stats`.
void count_cells(const CellFlags& flags, std::size_t first_row, std::size_t rows, unsigned threads,
                 StageStats& stats) {
  std::mutex merge;
  parallel_for(rows, threads, [&](std::size_t begin, std::size_t end) {
    StageStats local;
    for (std::size_t p = first_row + begin; p < first_row + end; ++p) {
      const std::uint8_t* f = flags.row(p);
      for (std::size_t i = 0; i < flags.cols(); ++i) {
        const std::uint8_t v = f[i];
        if (!v) continue;
        local.valid += (v & cell::valid) != 0;
        local.hidden += (v & cell::hidden) != 0;
        local.occluding += (v & cell::occluding) != 0;
        local.candidate += (v & cell::candidate) != 0;
        local.filtered += (v & cell::filtered) != 0;
        local.thinned += (v & cell::thinned) != 0;
      }
    }
    std::lock_guard<std::mutex> lock(merge);
    stats.valid += local.valid, stats.hidden += local.hidden, stats.occluding += local.occluding;
    stats.candidate += local.candidate, stats.filtered += local.filtered;
    stats.thinned += local.thinned;
  });
}

}  // namespace

std::vector<StageFigure> stage_figures(const StageStats& s) {
  return {{"hidden_pct", s.pct(s.hidden), false},
          {"occluding_pct", s.pct(s.occluding), false},
          {"cset_pct", s.pct(s.candidate), false},
          {"fset_pct", s.pct(s.filtered), false},
          {"tset_pct", s.pct(s.thinned), false},
          {"gset_pct", s.pct(s.generalised), false},
          {"factual_strokes", static_cast<double>(s.factual_strokes), true},
          {"formulated_strokes", static_cast<double>(s.formulated_strokes), true}};
}

struct SilhouetteStream::State {
  OrientedFrame frame;
  GeoTransform geotransform;
  SilhouetteParams params;
  double z_ref;
  ProgressFn progress;
  std::size_t next_profile = 0;
  ChainLinker factual{true, 0}, formulated{false, 0};
  // Cells of the chains still open, by slot, and the strokes of the closed ones with their id.
  std::vector<std::vector<StrokeCell>> open_factual, open_formulated;
  std::vector<std::pair<std::size_t, Stroke>> done_factual, done_formulated;
  SilhouetteResult result;

  State(const OrientedFrame& f, const GeoTransform& gt, const SilhouetteParams& p, double z,
        const ProgressFn& pr)
      : frame(f),
        geotransform(gt),
        params(p),
        z_ref(z),
        progress(pr),
        formulated(false, p.chain.window) {}

  // Moves the cells of profile candidates into their chains and finishes the closed chains.
  void link(ChainLinker& linker, ProfileCandidates&& candidates, std::vector<StrokeCell>&& cells,
            std::vector<std::vector<StrokeCell>>& open,
            std::vector<std::pair<std::size_t, Stroke>>& done, StrokeClass cls) {
    const auto& joined = linker.add_profile(std::move(candidates));
    if (open.size() < linker.slot_count()) open.resize(linker.slot_count());
    for (std::size_t k = 0; k < joined.size(); ++k) open[joined[k].slot].push_back(cells[k]);
    close(linker.closed(), open, done, cls);
  }

  // Keeps the strokes of closed chains long enough to draw; their slots' storage is reused.
  void close(const std::vector<ChainRef>& chains, std::vector<std::vector<StrokeCell>>& open,
             std::vector<std::pair<std::size_t, Stroke>>& done, StrokeClass cls) {
    for (const ChainRef& chain : chains) {
      std::vector<StrokeCell>& cells = open[chain.slot];
      if (static_cast<int>(cells.size()) >= params.chain.min_cells) {
        done.emplace_back(chain.id, stroke_from_cells(cells, cls));
      }
      cells.clear();
    }
  }
};

SilhouetteStream::SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                                   const SilhouetteParams& params, double z_ref,
                                   const ProgressFn& progress)
    : state_(std::make_unique<State>(frame, geotransform, params, z_ref, progress)) {
  params.validate();
}

SilhouetteStream::~SilhouetteStream() = default;

void SilhouetteStream::add_strip(const HeightGrid& z, std::size_t first, std::size_t count,
                                 bool keep_flags) {
  State& st = *state_;
  const OrientedFrame& frame = st.frame;
  const std::size_t before = first > 0 ? 1 : 0;
  const std::size_t after = first + count < frame.profiles ? 1 : 0;
  if (first != st.next_profile || count == 0 || z.rows() != before + count + after ||
      z.cols() != frame.length) {
    throw Error("strip of profiles does not follow the previous one or does not match the frame");
  }
  st.next_profile = first + count;
  const unsigned threads = st.params.threads;
  const ViewParams& view = st.params.view;
  StageTimings& time = st.result.timings;
  // Progress of stage `index` (of 6) within this strip, mapped onto the whole grid.
  auto progress_of = [&](int index) -> ProgressFn {
    if (!st.progress) return {};
    return [&st, first, count, index, total = frame.profiles](double fraction) {
      return st.progress(
          (static_cast<double>(first) + static_cast<double>(count) * (index + fraction) / 6.0) /
          static_cast<double>(total));
    };
  };

  CellFlags flags;
  auto start = Clock::now();
  classify_visibility(z, frame.d, view, flags, threads, progress_of(0));
  time.visibility += seconds_since(start);
  start = Clock::now();
  select_candidates(z, frame.d, view, flags, threads, progress_of(1));
  time.candidates += seconds_since(start);
  start = Clock::now();
  apply_slope_filter(z, frame.d, frame.w, st.params.filter, flags, threads, progress_of(2));
  time.filter += seconds_since(start);
  start = Clock::now();
  thin(flags, st.params.placement, threads, progress_of(3));
  time.thinning += seconds_since(start);

  start = Clock::now();
  count_cells(flags, before, count, threads, st.result.stats);
  const StrokeContext context{
      z,        flags,         frame, view, st.geotransform, st.params.geometry, st.params.subcell,
      st.z_ref, first - before};
  // Batches of profiles: candidates and their cell records are collected in parallel, then
  // linked in order on a thread of their own while the next batch is collected.
  constexpr std::size_t kBatch = 256;
  struct Collected {
    ProfileCandidates factual, formulated;
    std::vector<StrokeCell> factual_cells, formulated_cells;
  };
  // With one thread everything runs in turn (linking deferred); with more, one of them links.
  const unsigned workers = resolve_threads(threads);
  const unsigned collectors = workers > 1 ? workers - 1 : 1;
  auto collect = [&](std::size_t b0, std::vector<Collected>& batch) {
    batch.assign(std::min(kBatch, count - b0), {});
    parallel_for(batch.size(), collectors, [&](std::size_t lo, std::size_t hi) {
      for (std::size_t k = lo; k < hi; ++k) {
        const std::size_t row = before + b0 + k, p = first + b0 + k;
        Collected& c = batch[k];
        c.factual = profile_candidates(flags.row(row), frame.length, true);
        c.formulated = profile_candidates(flags.row(row), frame.length, false);
        for (std::int32_t i : c.factual.cell)
          c.factual_cells.push_back(stroke_cell(context, p, static_cast<std::size_t>(i), true));
        for (std::int32_t i : c.formulated.cell)
          c.formulated_cells.push_back(stroke_cell(context, p, static_cast<std::size_t>(i), false));
      }
    });
  };
  auto link = [&st](std::vector<Collected>& batch) {
    for (Collected& c : batch) {
      st.link(st.factual, std::move(c.factual), std::move(c.factual_cells), st.open_factual,
              st.done_factual, StrokeClass::factual);
      st.link(st.formulated, std::move(c.formulated), std::move(c.formulated_cells),
              st.open_formulated, st.done_formulated, StrokeClass::formulated);
    }
  };
  const ProgressFn link_progress = progress_of(4);
  std::vector<Collected> linking, collecting;
  collect(0, linking);
  for (std::size_t b0 = 0; b0 < count; b0 += kBatch) {
    const std::size_t next = b0 + kBatch;
    // get() rethrows what linking threw; if collecting throws, the future waits for the linker.
    std::future<void> linked = std::async(workers > 1 ? std::launch::async : std::launch::deferred,
                                          link, std::ref(linking));
    if (next < count) collect(next, collecting);
    linked.get();
    std::swap(linking, collecting);
    if (link_progress && !link_progress(static_cast<double>(std::min(next, count)) / count)) {
      throw Cancelled();
    }
  }
  time.chaining += seconds_since(start);
  if (keep_flags) st.result.flags = std::move(flags);
}

SilhouetteResult SilhouetteStream::finish() {
  State& st = *state_;
  if (st.next_profile != st.frame.profiles) throw Error("not every profile was delivered");
  const auto start = Clock::now();
  st.close(st.factual.close_all(), st.open_factual, st.done_factual, StrokeClass::factual);
  st.close(st.formulated.close_all(), st.open_formulated, st.done_formulated,
           StrokeClass::formulated);
  SilhouetteResult& result = st.result;
  StageStats& stats = result.stats;
  // Strokes in the order their chains were started: the order of SPEC 1.7's scan.
  for (auto* done : {&st.done_factual, &st.done_formulated}) {
    std::sort(done->begin(), done->end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (auto& entry : *done) {
      stats.generalised += static_cast<std::size_t>(entry.second.cells);
      result.strokes.push_back(std::move(entry.second));
    }
  }
  stats.factual_strokes = st.done_factual.size();
  stats.formulated_strokes = st.done_formulated.size();
  result.timings.strokes += seconds_since(start);
  if (st.progress && !st.progress(1.0)) throw Cancelled();
  return std::move(result);
}

SilhouetteResult run_in_strips(const OrientedFrame& frame, const GeoTransform& geotransform,
                               const SilhouetteParams& params, double z_ref, std::size_t strip,
                               const ProfileReader& read, const ProgressFn& progress) {
  if (strip == 0) throw Error("a strip needs at least one profile");
  SilhouetteStream stream(frame, geotransform, params, z_ref, progress);
  for (std::size_t first = 0; first < frame.profiles; first += strip) {
    const std::size_t count = std::min(strip, frame.profiles - first);
    const std::size_t lo = first > 0 ? first - 1 : 0;
    const std::size_t hi = std::min(frame.profiles, first + count + 1);
    stream.add_strip(read(lo, hi - lo), first, count);
  }
  return stream.finish();
}

std::size_t automatic_strip_profiles(std::size_t rows, std::size_t cols, bool resampled) {
  if (resampled) return 0;
  const double memory =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  const double bytes = 5.0 * static_cast<double>(rows) * static_cast<double>(cols);
  return memory > 0 && bytes > 0.5 * memory ? 1024 : 0;
}

SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const SilhouetteParams& params,
                                 const ProgressFn& progress) {
  params.validate();
  if (oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("oriented grid does not match its frame");
  }
  SilhouetteStream stream(frame, geotransform, params, lowest_height(oriented), progress);
  stream.add_strip(oriented, 0, frame.profiles, true);
  return stream.finish();
}

}  // namespace tsk
