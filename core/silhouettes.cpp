#include "silhouettes.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <functional>
#include <future>
#include <iterator>
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

// True when the eight heights from z on are all nodata (NaN or infinite: every exponent bit set).
static_assert(std::numeric_limits<float>::is_iec559, "eight_nodata reads IEEE 754 floats");
bool eight_nodata(const float* z) {
  constexpr std::uint32_t kExponent = 0x7f800000u;
  std::uint32_t bits[8];
  std::memcpy(bits, z, sizeof bits);
  std::uint32_t common = kExponent;
  for (std::uint32_t b : bits) common &= b;
  return common == kExponent;
}

// Cells [begin, end) of a profile: from its first to its last cell with data. The nodata margins
// of a resampled profile can be half of it, so they are skipped eight cells at a time.
std::pair<std::size_t, std::size_t> data_range(const float* z, std::size_t length) {
  std::size_t begin = 0, end = length;
  while (begin + 8 <= end && eight_nodata(z + begin)) begin += 8;
  while (begin < end && !is_data(z[begin])) ++begin;
  while (end >= begin + 8 && eight_nodata(z + end - 8)) end -= 8;
  while (end > begin && !is_data(z[end - 1])) --end;
  return {begin, end};
}

// The stage counts in the order of their flags' bits.
constexpr std::size_t StageStats::*kCountOfBit[] = {&StageStats::valid,     &StageStats::hidden,
                                                    &StageStats::occluding, &StageStats::candidate,
                                                    &StageStats::filtered,  &StageStats::thinned};
static_assert(cell::valid == 1 && cell::hidden == 2 && cell::occluding == 4 &&
                  cell::candidate == 8 && cell::filtered == 16 && cell::thinned == 32,
              "kCountOfBit lists the counts bit by bit");
constexpr std::size_t kCounted = std::size(kCountOfBit);

// Adds the classification counts of one profile to `stats`. Eight cells at a time: byte k of
// lanes[b] counts flag b of every eighth cell, for at most 255 words before it is summed.
void count_profile(const std::uint8_t* f, std::size_t length, StageStats& stats) {
  constexpr std::uint64_t kLowBits = 0x0101010101010101ull;
  constexpr std::uint64_t kEvenBytes = 0x00ff00ff00ff00ffull;
  std::size_t totals[kCounted] = {};
  std::size_t i = 0;
  while (i + 8 <= length) {
    std::uint64_t lanes[kCounted] = {};
    const std::size_t words = std::min<std::size_t>((length - i) / 8, 255);
    for (std::size_t w = 0; w < words; ++w, i += 8) {
      std::uint64_t word;
      std::memcpy(&word, f + i, sizeof word);
      for (std::size_t b = 0; b < kCounted; ++b) lanes[b] += (word >> b) & kLowBits;
    }
    for (std::size_t b = 0; b < kCounted; ++b) {
      // Byte lanes to 16-bit lanes (each at most 510), then their sum in the top 16 bits.
      const std::uint64_t pairs = (lanes[b] & kEvenBytes) + ((lanes[b] >> 8) & kEvenBytes);
      totals[b] += (pairs * 0x0001000100010001ull) >> 48;
    }
  }
  for (; i < length; ++i)
    for (std::size_t b = 0; b < kCounted; ++b) totals[b] += (f[i] >> b) & 1u;
  for (std::size_t b = 0; b < kCounted; ++b) stats.*kCountOfBit[b] += totals[b];
}

void add_counts(const StageStats& counts, StageStats& stats) {
  stats.valid += counts.valid, stats.hidden += counts.hidden;
  stats.occluding += counts.occluding, stats.candidate += counts.candidate;
  stats.filtered += counts.filtered, stats.thinned += counts.thinned;
}

// The stages that run profile by profile inside add_strip.
constexpr double StageTimings::*kProfileStages[] = {
    &StageTimings::visibility, &StageTimings::candidates, &StageTimings::filter,
    &StageTimings::thinning, &StageTimings::chaining};

// The stages are timed on every eighth profile, their times counted eight times: reading the
// clock ten times a profile would cost more than the stages of profiles a few cells long.
constexpr std::size_t kTimedEvery = 8;

// Runs `work`, adding the time it takes to `stage` of `seconds` if `timed`.
template <typename Work>
void time_stage(bool timed, StageTimings& seconds, double StageTimings::*stage, Work&& work) {
  if (!timed) return work();
  const auto start = Clock::now();
  work();
  seconds.*stage += seconds_since(start);
}

// Splits `wall` seconds between the per-profile stages by their shares of the threads' time
// `seconds` (summed over the threads), adding them to `timings`.
void share_out(const StageTimings& seconds, double wall, StageTimings& timings) {
  double total = 0;
  for (auto stage : kProfileStages) total += seconds.*stage;
  if (!(total > 0)) return;
  for (auto stage : kProfileStages) timings.*stage += wall * (seconds.*stage / total);
}

// The plan-oblique reference: the lowest height of `z`. Map geometry needs none, which spares a
// pass over the grid.
double plan_oblique_reference(const HeightGrid& z, const SilhouetteParams& params) {
  return params.geometry == Geometry::oblique ? lowest_height(z) : 0.0;
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
  // One class of strokes: its linker, the strokes of its open chains by slot, and its complete
  // strokes waiting until every chain started before theirs is complete too.
  struct Strokes {
    Strokes(bool factual, int window)
        : linker(factual, window), cls(factual ? StrokeClass::factual : StrokeClass::formulated) {}
    ChainLinker linker;
    StrokeClass cls;
    std::vector<StrokeBuilder> open;
    std::vector<std::pair<std::size_t, Stroke>> waiting;  // a heap, the oldest chain on top
    std::vector<Stroke> handed_on;                        // without a sink
    std::size_t count = 0, cells = 0;                     // of the strokes handed on
  };

  OrientedFrame frame;
  GeoTransform geotransform;
  SilhouetteParams params;
  double z_ref;
  ProgressFn progress;
  StrokeSink sink;
  std::size_t next_profile = 0;
  Strokes factual{true, 0}, formulated;
  CellFlags flags;  // the current strip's classification, its memory reused by the next strip
  SilhouetteResult result;

  State(const OrientedFrame& f, const GeoTransform& gt, const SilhouetteParams& p, double z,
        const ProgressFn& pr, StrokeSink sk)
      : frame(f),
        geotransform(gt),
        params(p),
        z_ref(z),
        progress(pr),
        sink(std::move(sk)),
        formulated(false, p.chain.window) {}

  // Adds the cells of a profile's candidates to the strokes of their chains, finishes the closed
  // chains and hands on the strokes no open chain precedes.
  void link(Strokes& strokes, const ProfileCandidates& candidates,
            const std::vector<StrokeCell>& cells) {
    const auto& joined = strokes.linker.add_profile(candidates);
    std::vector<StrokeBuilder>& open = strokes.open;
    if (open.size() < strokes.linker.slot_count()) open.resize(strokes.linker.slot_count());
    for (std::size_t k = 0; k < joined.size(); ++k) open[joined[k].slot].add(cells[k]);
    close(strokes, strokes.linker.closed());
    hand_on(strokes, strokes.linker.oldest_open());
  }

  // Keeps the strokes of closed chains long enough to draw; their slots' storage is reused.
  void close(Strokes& strokes, const std::vector<ChainRef>& chains) {
    for (const ChainRef& chain : chains) {
      StrokeBuilder& builder = strokes.open[chain.slot];
      if (builder.cells() >= params.chain.min_cells) {
        strokes.waiting.emplace_back(chain.id, builder.stroke(strokes.cls));
        std::push_heap(strokes.waiting.begin(), strokes.waiting.end(), later_chain);
      }
      builder.clear();
    }
  }

  // Hands on the waiting strokes of chains started before chain `id`, oldest first.
  void hand_on(Strokes& strokes, std::size_t id) {
    auto& waiting = strokes.waiting;
    while (!waiting.empty() && waiting.front().first < id) {
      std::pop_heap(waiting.begin(), waiting.end(), later_chain);
      Stroke stroke = std::move(waiting.back().second);
      waiting.pop_back();
      ++strokes.count;
      strokes.cells += static_cast<std::size_t>(stroke.cells);
      if (sink) {
        sink(std::move(stroke));
      } else {
        strokes.handed_on.push_back(std::move(stroke));
      }
    }
  }

  static bool later_chain(const std::pair<std::size_t, Stroke>& a,
                          const std::pair<std::size_t, Stroke>& b) {
    return a.first > b.first;
  }
};

SilhouetteStream::SilhouetteStream(const OrientedFrame& frame, const GeoTransform& geotransform,
                                   const SilhouetteParams& params, double z_ref,
                                   const ProgressFn& progress, StrokeSink sink)
    : state_(
          std::make_unique<State>(frame, geotransform, params, z_ref, progress, std::move(sink))) {
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
  // Every stage runs on one profile after the other while its cells are in cache: the stages
  // of a profile need only its heights, its neighbours' heights and its own flags. Batches of
  // profiles are classified and their chain candidates collected in parallel, then linked in
  // order on a thread of their own while the next batch is collected.
  CellFlags& flags = st.flags;  // rows of the neighbours stay unused
  flags.reshape(z.rows(), z.cols(), kUnset);
  const std::size_t length = frame.length;
  const StrokeContext context{
      z,        flags,         frame, view, st.geotransform, st.params.geometry, st.params.subcell,
      st.z_ref, first - before};
  // Batches of about a million cells, at least 256 profiles. Short profiles come in more to a
  // batch, as every batch costs a thread start or two whatever its size.
  const std::size_t batch_profiles = std::clamp<std::size_t>(
      (std::size_t{1} << 20) / std::max<std::size_t>(1, length), 256, 16384);
  struct Collected {
    ProfileCandidates factual, formulated;
    std::vector<StrokeCell> factual_cells, formulated_cells;
  };
  std::mutex merge;
  StageTimings seconds;  // time of each stage summed over the threads
  auto collect = [&](std::size_t b0, std::vector<Collected>& batch) {
    batch.resize(std::min(batch_profiles, count - b0));  // every entry refilled, storage reused
    parallel_for(batch.size(), resolve_threads(threads), [&](std::size_t lo, std::size_t hi) {
      StageTimings local;
      StageStats counts;
      for (std::size_t k = lo; k < hi; ++k) {
        const std::size_t row = before + b0 + k, p = first + b0 + k;
        std::uint8_t* f = flags.row(row);
        const float* zp = z.row(row);
        // Every stage skips the nodata before the first and after the last cell with data:
        // up to half of a resampled profile.
        // (Named variables, not a structured binding: C++17 lambdas cannot capture those.)
        const std::pair<std::size_t, std::size_t> range = data_range(zp, length);
        const std::size_t b = range.first, e = range.second;
        const bool timed = p % kTimedEvery == 0;
        time_stage(timed, local, &StageTimings::visibility, [&] {
          std::memset(f, 0, length);
          classify_profile_visibility(zp, f, e, frame.d, view, b);
        });
        time_stage(timed, local, &StageTimings::candidates,
                   [&] { select_profile_candidates(zp + b, f + b, e - b, frame.d, view); });
        time_stage(timed, local, &StageTimings::filter, [&] {
          ProfileRows rows = profile_rows(z, row);
          for (const float** r : {&rows.left, &rows.centre, &rows.right})
            if (*r) *r += b;
          filter_profile(rows, f + b, e - b, frame.d, frame.w, st.params.filter);
        });
        time_stage(timed, local, &StageTimings::thinning,
                   [&] { thin_profile(f + b, e - b, st.params.placement); });
        time_stage(timed, local, &StageTimings::chaining, [&] {
          count_profile(f + b, e - b, counts);
          Collected& c = batch[k];
          profile_candidates(f, e, true, c.factual, b);
          profile_candidates(f, e, false, c.formulated, b);
          c.factual_cells.clear();
          c.formulated_cells.clear();
          for (std::int32_t i : c.factual.cell)
            c.factual_cells.push_back(stroke_cell(context, p, static_cast<std::size_t>(i), true));
          for (std::int32_t i : c.formulated.cell) {
            c.formulated_cells.push_back(
                stroke_cell(context, p, static_cast<std::size_t>(i), false));
          }
        });
      }
      std::lock_guard<std::mutex> lock(merge);
      for (auto stage : kProfileStages) seconds.*stage += kTimedEvery * local.*stage;
      add_counts(counts, st.result.stats);
    });
  };
  auto link = [&st, &seconds, &merge](const std::vector<Collected>& batch) {
    const auto start = Clock::now();
    for (const Collected& c : batch) {
      st.link(st.factual, c.factual, c.factual_cells);
      st.link(st.formulated, c.formulated, c.formulated_cells);
    }
    std::lock_guard<std::mutex> lock(merge);
    seconds.chaining += seconds_since(start);
  };
  // With one thread everything runs in turn (linking deferred).
  const auto launch = resolve_threads(threads) > 1 ? std::launch::async : std::launch::deferred;
  const auto start = Clock::now();
  std::vector<Collected> linking, collecting;
  collect(0, linking);
  for (std::size_t b0 = 0; b0 < count; b0 += batch_profiles) {
    const std::size_t next = b0 + batch_profiles;
    // get() rethrows what linking threw; if collecting throws, the future waits for the linker.
    std::future<void> linked = std::async(launch, link, std::cref(linking));
    if (next < count) collect(next, collecting);
    linked.get();
    std::swap(linking, collecting);
    if (st.progress && !st.progress((static_cast<double>(first) + std::min(next, count)) /
                                    static_cast<double>(frame.profiles))) {
      throw Cancelled();
    }
  }
  share_out(seconds, seconds_since(start), st.result.timings);
  if (keep_flags) {
    st.result.flags = std::move(flags);
    flags = CellFlags();
  }
}

SilhouetteResult SilhouetteStream::finish() {
  State& st = *state_;
  if (st.next_profile != st.frame.profiles) throw Error("not every profile was delivered");
  const auto start = Clock::now();
  for (State::Strokes* strokes : {&st.factual, &st.formulated}) {
    st.close(*strokes, strokes->linker.close_all());
    st.hand_on(*strokes, std::numeric_limits<std::size_t>::max());
  }
  SilhouetteResult& result = st.result;
  StageStats& stats = result.stats;
  stats.generalised = st.factual.cells + st.formulated.cells;
  stats.factual_strokes = st.factual.count;
  stats.formulated_strokes = st.formulated.count;
  // Without a sink: factual strokes first, then formulated, each in the order of the scan.
  result.strokes = std::move(st.factual.handed_on);
  result.strokes.reserve(result.strokes.size() + st.formulated.handed_on.size());
  for (Stroke& stroke : st.formulated.handed_on) result.strokes.push_back(std::move(stroke));
  result.timings.strokes += seconds_since(start);
  if (st.progress && !st.progress(1.0)) throw Cancelled();
  return std::move(result);
}

namespace {

bool over_half_the_memory(double bytes) {
  const double memory =
      static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
  return memory > 0 && bytes > 0.5 * memory;
}

// What a strip-by-strip run holds per profile of a strip: two strips of heights (the one processed
// and the one being read), the classification and, resampled, the band of DEM cells.
double strip_bytes_per_profile(const OrientedFrame& frame) {
  return (frame.resampled ? 13.0 : 9.0) *
         static_cast<double>(std::max<std::size_t>(1, frame.length));
}

}  // namespace

SilhouetteResult run_in_strips(const OrientedFrame& frame, const GeoTransform& geotransform,
                               const SilhouetteParams& params, double z_ref, std::size_t strip,
                               const ProfileReader& read, const ProgressFn& progress,
                               StrokeSink sink) {
  if (strip == 0) throw Error("a strip needs at least one profile");
  const std::size_t held = std::min(strip, frame.profiles) + 2;
  if (over_half_the_memory(strip_bytes_per_profile(frame) * static_cast<double>(held))) {
    throw Error("strips of " + std::to_string(strip) + " profiles of " +
                std::to_string(frame.length) +
                " cells would take more than half of this machine's memory; choose fewer "
                "profiles per strip (0 chooses them)");
  }
  SilhouetteStream stream(frame, geotransform, params, z_ref, progress, std::move(sink));
  // The strip starting at `first` with its neighbours.
  auto read_strip = [&](std::size_t first, HeightGrid& heights) {
    const std::size_t lo = first > 0 ? first - 1 : 0;
    const std::size_t hi = std::min(frame.profiles, first + strip + 1);
    read(lo, hi - lo, heights);
  };
  // The next strip is read while this one is processed, into memory of its own, by a reader of
  // its own.
  HeightGrid current, next;
  Worker reader(resolve_threads(params.threads) > 1);
  reader.run([&] { read_strip(0, current); }).get();
  for (std::size_t first = 0; first < frame.profiles; first += strip) {
    std::future<void> reading;
    if (first + strip < frame.profiles)
      reading = reader.run([&, first] { read_strip(first + strip, next); });
    // If processing throws, the reader finishes the read before it goes.
    stream.add_strip(current, first, std::min(strip, frame.profiles - first));
    if (reading.valid()) reading.get();
    std::swap(current, next);
  }
  return stream.finish();
}

SilhouetteResult run_resampled_silhouettes(const HeightGrid& dem, const OrientedFrame& frame,
                                           const GeoTransform& geotransform,
                                           const SilhouetteParams& params,
                                           const ProgressFn& progress) {
  params.validate();
  if (!frame.resampled) throw Error("run_resampled_silhouettes needs a resampled frame");
  // Big enough for the linking of one batch to overlap the collection of the next (add_strip),
  // small enough to stay a few tens of megabytes on any DEM.
  constexpr std::size_t kStrip = 1024;
  double resampling = 0;
  SilhouetteResult result = run_in_strips(
      frame, geotransform, params, plan_oblique_reference(dem, params), kStrip,
      [&](std::size_t first, std::size_t count, HeightGrid& strip) {
        const auto start = Clock::now();
        resample_profiles(dem, frame, first, count, strip, params.threads);
        resampling += seconds_since(start);
      },
      progress);
  result.timings.resampling = resampling;
  return result;
}

bool too_large_to_turn_whole(const OrientedFrame& frame) {
  const double dem = frame.resampled ? 4.0 * static_cast<double>(frame.dem_rows) *
                                           static_cast<double>(frame.dem_cols)
                                     : 0.0;
  return over_half_the_memory(dem + 5.0 * static_cast<double>(frame.profiles) *
                                        static_cast<double>(frame.length));
}

std::size_t strip_profiles(const OrientedFrame& frame) {
  constexpr double kBudget = 512.0 * 1024 * 1024;
  const double bytes_per_profile = strip_bytes_per_profile(frame);
  // Short profiles come more to a strip, at least 1 Mi cells, as every strip costs a read and a
  // pause in linking. (Not more for others: the first strip is read before any work starts.)
  const double most = std::clamp(
      std::floor(1024.0 * 1024 / static_cast<double>(std::max<std::size_t>(1, frame.length))),
      1024.0, 65536.0);
  return static_cast<std::size_t>(std::clamp(std::floor(kBudget / bytes_per_profile), 16.0, most));
}

SilhouetteResult run_silhouettes(const HeightGrid& oriented, const OrientedFrame& frame,
                                 const GeoTransform& geotransform, const SilhouetteParams& params,
                                 const ProgressFn& progress, std::optional<double> z_ref) {
  params.validate();
  if (oriented.rows() != frame.profiles || oriented.cols() != frame.length) {
    throw Error("oriented grid does not match its frame");
  }
  SilhouetteStream stream(frame, geotransform, params,
                          z_ref ? *z_ref : plan_oblique_reference(oriented, params), progress);
  stream.add_strip(oriented, 0, frame.profiles, true);
  return stream.finish();
}

}  // namespace tsk
