#include "core/drawn/stroke_joining.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "core/drawn/stroke_smoothing.h"

namespace tsk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// One end of a stroke: where it is and the direction it leaves the stroke in (0, 0 when the
// stroke has a single point).
struct StrokeEnd {
  StrokePoint at;
  double dx, dy;
};

std::size_t stroke_of(std::size_t end) {
  return end / 2;
}
bool is_start(std::size_t end) {
  return end % 2 == 0;
}

// The outward direction of an end, over about `reach` of the stroke's length, so that a stroke
// stepping from cell to cell still has the direction it runs in.
StrokeEnd stroke_end(const std::vector<StrokePoint>& pts, bool start, double reach) {
  const std::size_t n = pts.size();
  const StrokePoint at = start ? pts.front() : pts.back();
  StrokePoint from = at;
  double walked = 0.0;
  for (std::size_t k = 1; k < n && walked < reach; ++k) {
    const StrokePoint next = start ? pts[k] : pts[n - 1 - k];
    walked += distance(next, from);
    from = next;
  }
  const double len = distance(at, from);
  if (len <= 0.0) return {at, 0.0, 0.0};
  return {at, (at.x - from.x) / len, (at.y - from.y) / len};
}

// Cosine of the angle between two directions; NaN when either is missing.
double cosine_between(double ax, double ay, double bx, double by) {
  const double la = std::sqrt(ax * ax + ay * ay), lb = std::sqrt(bx * bx + by * by);
  if (la <= 0.0 || lb <= 0.0) return std::numeric_limits<double>::quiet_NaN();
  return std::clamp((ax * bx + ay * by) / (la * lb), -1.0, 1.0);
}

// An angle in degrees from its cosine; 180 for a missing direction's NaN.
double degrees_of(double cosine) {
  return std::isnan(cosine) ? 180.0 : std::acos(cosine) * 180.0 / kPi;
}

// Angle between two directions in degrees; 180 when either is missing.
double angle_between(double ax, double ay, double bx, double by) {
  return degrees_of(cosine_between(ax, ay, bx, by));
}

// The largest angle two joining ends may turn through, and its cosine.
struct AngleLimit {
  double deg, cos;
};

// Whether angle_between(a, b) is at most `limit.deg` (at most 90), mostly without its arc cosine:
// a cosine clear of the limit's by 1e-9 puts the angle more than 5e-8 degrees from it, far more
// than the rounding of either.
bool within_angle(double ax, double ay, double bx, double by, const AngleLimit& limit) {
  const double c = cosine_between(ax, ay, bx, by);
  constexpr double kClear = 1e-9;
  if (c > limit.cos + kClear) return true;
  if (c < limit.cos - kClear) return false;
  return degrees_of(c) <= limit.deg;
}

// Whether end a leads on into end b: within the gap, and every direction there is to compare (the
// ends' and the step's between them) within the angle, as within(ux, uy, vx, vy) says of each pair
// of directions compared.
template <typename Angle>
bool leads_on(const StrokeEnd& a, const StrokeEnd& b, const JoinRule& rule, Angle&& within) {
  const double gx = b.at.x - a.at.x, gy = b.at.y - a.at.y;
  const double gap = std::sqrt(gx * gx + gy * gy);
  if (gap > rule.gap) return false;
  const bool a_dir = a.dx != 0.0 || a.dy != 0.0, b_dir = b.dx != 0.0 || b.dy != 0.0;
  if (!a_dir && !b_dir) return false;
  if (a_dir && b_dir && !within(a.dx, a.dy, -b.dx, -b.dy)) return false;
  // A step shorter than a tenth of the gap has no direction of its own to compare.
  if (gap > 0.1 * rule.gap) {
    if (a_dir && !within(a.dx, a.dy, gx, gy)) return false;
    if (b_dir && !within(-b.dx, -b.dy, gx, gy)) return false;
  }
  return true;
}

// Whether end a leads on into end b (join_cost is not negative), without the cost: what grouping
// asks of every pair of ends near each other.
bool may_join(const StrokeEnd& a, const StrokeEnd& b, const JoinRule& rule,
              const AngleLimit& limit) {
  return leads_on(a, b, rule, [&](double ux, double uy, double vx, double vy) {
    return within_angle(ux, uy, vx, vy, limit);
  });
}

// How badly end a leads on into end b (smaller is better), or a negative value when it does not.
double join_cost(const StrokeEnd& a, const StrokeEnd& b, const JoinRule& rule) {
  double worst = 0.0;
  const bool joins = leads_on(a, b, rule, [&](double ux, double uy, double vx, double vy) {
    worst = std::max(worst, angle_between(ux, uy, vx, vy));
    return worst <= rule.angle_deg;
  });
  if (!joins) return -1.0;
  const double gap = distance(a.at, b.at);
  return gap / std::max(rule.gap, 1e-300) + worst / std::max(rule.angle_deg, 1e-9);
}

struct EndPair {
  double cost;
  std::uint32_t a, b;
};

// The first end of each bucket that has had one, by bucket key: an open-addressing table, as the
// buckets are looked up several times for every stroke added.
class BucketHeads {
 public:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  explicit BucketHeads(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected) capacity *= 2;
    slots_.assign(capacity, {kEmpty, kNone});
  }
  // The head of bucket `key`, made (with none) if it has none yet.
  std::uint32_t& operator[](std::uint64_t key) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    Slot& slot = slots_[find_slot(key)];
    if (slot.key == kEmpty) slot.key = key, ++used_;
    return slot.head;
  }
  // The head of bucket `key`, or kNone.
  std::uint32_t head(std::uint64_t key) const {
    const Slot& slot = slots_[find_slot(key)];
    return slot.key == kEmpty ? kNone : slot.head;
  }
  // Empties every bucket, keeping the table's storage.
  void clear() {
    std::fill(slots_.begin(), slots_.end(), Slot{kEmpty, kNone});
    used_ = 0;
  }
  // The slot bucket `key` is looked for from, to prefetch.
  const void* home_slot(std::uint64_t key) const { return &slots_[home(key)]; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  struct Slot {
    std::uint64_t key;
    std::uint32_t head;
  };
  // The slot a key is looked for from: the product's high half, which every bit of the key
  // moves (its low bits left out the bucket's column, and a row of buckets probed as one run).
  std::size_t home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 32) & (slots_.size() - 1);
  }
  std::size_t find_slot(std::uint64_t key) const {
    const std::size_t mask = slots_.size() - 1;
    std::size_t k = home(key);
    while (slots_[k].key != key && slots_[k].key != kEmpty) k = (k + 1) & mask;
    return k;
  }
  void grow() {
    std::vector<Slot> old(2 * slots_.size(), {kEmpty, kNone});
    old.swap(slots_);
    for (const Slot& slot : old)
      if (slot.key != kEmpty) slots_[find_slot(slot.key)] = slot;
  }
  std::vector<Slot> slots_;
  std::size_t used_ = 0;
};

// Ends in square buckets, to find the ends within a radius of a point; ends can come and go.
// Each bucket lists its ends through `next_`, so that adding an end allocates nothing once its
// bucket is known.
class EndIndex {
 public:
  explicit EndIndex(double radius, std::size_t expected = 0)
      : size_(std::max(2.0 * radius, 1e-9)), heads_(expected) {}
  void insert(std::uint32_t end, StrokePoint at) {
    const std::size_t k = end - first_held_;
    if (next_.size() <= k) next_.resize(std::max<std::size_t>(k + 1, 2 * next_.size()), kNone);
    std::uint32_t& head = heads_[key(at)];
    next_[k] = head;
    head = end;
  }
  // Empties the index, keeping its storage, for ends from `first` on.
  void clear(std::uint32_t first) {
    heads_.clear();
    next_.clear();
    first_held_ = first;
  }
  // Calls f(end) for every end that may lie within `radius` of p: buckets are twice the radius
  // wide, so those in the 2 x 2 buckets nearest p.
  template <typename F>
  void near(StrokePoint p, F&& f) const {
    for_near_buckets(p, [&](std::uint64_t key) {
      for (std::uint32_t e = heads_.head(key); e != kNone; e = next(e)) f(e);
    });
  }
  // Where near(p) starts looking, the table's slots of its buckets, into `slots` (four): a cache
  // miss each in a table of many buckets (a third of StrokeGrouper::add's time).
  void near_slots(StrokePoint p, const void** slots) const {
    for_near_buckets(p, [&](std::uint64_t key) { *slots++ = heads_.home_slot(key); });
  }

 private:
  static constexpr std::uint32_t kNone = BucketHeads::kNone;
  std::uint32_t& next(std::uint32_t end) { return next_[end - first_held_]; }
  std::uint32_t next(std::uint32_t end) const { return next_[end - first_held_]; }
  // Calls f(key) for the 2 x 2 buckets nearest p.
  template <typename F>
  void for_near_buckets(StrokePoint p, F&& f) const {
    const double ux = p.x / size_, uy = p.y / size_;
    const auto bx = static_cast<std::int64_t>(std::floor(ux));
    const auto by = static_cast<std::int64_t>(std::floor(uy));
    const std::int64_t sx = ux - static_cast<double>(bx) < 0.5 ? -1 : 1;
    const std::int64_t sy = uy - static_cast<double>(by) < 0.5 ? -1 : 1;
    for (std::int64_t cy : {by, by + sy}) {
      for (std::int64_t cx : {bx, bx + sx}) f(key(cx, cy));
    }
  }
  std::int64_t bucket(double v) const { return static_cast<std::int64_t>(std::floor(v / size_)); }
  std::uint64_t key(StrokePoint at) const { return key(bucket(at.x), bucket(at.y)); }
  static std::uint64_t key(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(bx) << 32) ^ (static_cast<std::uint64_t>(by) & 0xffffffffu);
  }
  double size_;
  BucketHeads heads_;
  std::vector<std::uint32_t> next_;  // by end from first_held_ on: the next end in its bucket
  std::uint32_t first_held_ = 0;
};

// Every pair of ends of different strokes that may join, best first. Most groups are a few
// strokes, whose ends are simply tried against each other.
std::vector<EndPair> candidate_pairs(const std::vector<StrokeEnd>& ends, const JoinRule& rule) {
  std::vector<EndPair> pairs;
  const auto try_pair = [&](std::size_t a, std::size_t b) {
    if (b <= a || stroke_of(b) == stroke_of(a)) return;
    const double cost = join_cost(ends[a], ends[b], rule);
    if (cost >= 0.0)
      pairs.push_back({cost, static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)});
  };
  constexpr std::size_t kFewEnds = 64;
  if (ends.size() <= kFewEnds) {
    for (std::size_t a = 0; a < ends.size(); ++a)
      for (std::size_t b = a + 1; b < ends.size(); ++b) try_pair(a, b);
  } else {
    EndIndex index(rule.gap, ends.size());
    for (std::size_t e = 0; e < ends.size(); ++e)
      index.insert(static_cast<std::uint32_t>(e), ends[e].at);
    for (std::size_t a = 0; a < ends.size(); ++a)
      index.near(ends[a].at, [&](std::uint32_t b) { try_pair(a, b); });
  }
  std::sort(pairs.begin(), pairs.end(), [](const EndPair& x, const EndPair& y) {
    return x.cost != y.cost ? x.cost < y.cost : std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
  });
  return pairs;
}

std::size_t find_root(std::vector<std::size_t>& parent, std::size_t s) {
  while (parent[s] != s) s = parent[s] = parent[parent[s]];
  return s;
}

// For each end, the end it joins (or itself): best pairs first, each end once, no loops.
std::vector<std::size_t> choose_partners(const std::vector<StrokeEnd>& ends, const JoinRule& rule) {
  std::vector<std::size_t> partner(ends.size());
  std::iota(partner.begin(), partner.end(), std::size_t{0});
  std::vector<std::size_t> group(ends.size() / 2);
  std::iota(group.begin(), group.end(), std::size_t{0});
  for (const EndPair& pair : candidate_pairs(ends, rule)) {
    if (partner[pair.a] != pair.a || partner[pair.b] != pair.b) continue;
    const std::size_t ga = find_root(group, stroke_of(pair.a));
    const std::size_t gb = find_root(group, stroke_of(pair.b));
    if (ga == gb) continue;
    group[ga] = gb;
    partner[pair.a] = pair.b;
    partner[pair.b] = pair.a;
  }
  return partner;
}

// Weighted mean of two values, the finite one alone when the other is not.
double merged_mean(double a, double wa, double b, double wb) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return (a * wa + b * wb) / (wa + wb);
}

// (Element by element: GCC 14 warns falsely about a range insert here, -Wstringop-overflow.)
template <typename T>
void append_in_order(std::vector<T>& into, const std::vector<T>& from, bool reversed) {
  into.reserve(into.size() + from.size());
  if (reversed) {
    for (auto it = from.rbegin(); it != from.rend(); ++it) into.push_back(*it);
  } else {
    for (const T& v : from) into.push_back(v);
  }
}

// Appends `piece` to `joined`, reversed when it is entered at its last point.
void append_piece(Stroke& joined, Stroke& piece, bool reversed) {
  if (joined.points.empty()) {
    joined = std::move(piece);
    if (reversed) {
      std::reverse(joined.points.begin(), joined.points.end());
      std::reverse(joined.vertices.begin(), joined.vertices.end());
      std::reverse(joined.chain.begin(), joined.chain.end());
    }
    return;
  }
  const StrokePoint last = joined.points.back();
  const StrokePoint first = reversed ? piece.points.back() : piece.points.front();
  const double wa = joined.cells, wb = piece.cells;
  joined.mean_slope_pct = merged_mean(joined.mean_slope_pct, wa, piece.mean_slope_pct, wb);
  joined.mean_row_slope_pct =
      merged_mean(joined.mean_row_slope_pct, wa, piece.mean_row_slope_pct, wb);
  joined.mean_depth_m = merged_mean(joined.mean_depth_m, wa, piece.mean_depth_m, wb);
  joined.mean_dist = merged_mean(joined.mean_dist, wa, piece.mean_dist, wb);
  joined.mean_z = merged_mean(joined.mean_z, wa, piece.mean_z, wb);
  if (std::isfinite(piece.max_depth_m))
    joined.max_depth_m = std::isfinite(joined.max_depth_m)
                             ? std::max(joined.max_depth_m, piece.max_depth_m)
                             : piece.max_depth_m;
  joined.length += distance(first, last) + piece.length;
  joined.cells += piece.cells;
  append_in_order(joined.points, piece.points, reversed);
  append_in_order(joined.vertices, piece.vertices, reversed);
  append_in_order(joined.chain, piece.chain, reversed);
}

// The ends of every stroke: stroke k's start at 2k, its last point at 2k + 1.
std::vector<StrokeEnd> stroke_ends(const std::vector<Stroke>& strokes, const JoinRule& rule) {
  std::vector<StrokeEnd> ends;
  ends.reserve(2 * strokes.size());
  for (const Stroke& s : strokes) {
    ends.push_back(stroke_end(s.points, true, 2.0 * rule.gap));
    ends.push_back(stroke_end(s.points, false, 2.0 * rule.gap));
  }
  return ends;
}

// The pieces of a joined stroke (entered at the ends in `walk`) that it keeps, [first, second):
// short pieces are left off its ends, so that they stay only where they close a gap between
// longer ones (none stay of a stroke joined of short pieces only).
std::pair<std::size_t, std::size_t> kept_span(const std::vector<std::size_t>& walk,
                                              const std::vector<Stroke>& strokes,
                                              const JoinRule& rule) {
  const auto is_short = [&](std::size_t entry) {
    return strokes[stroke_of(entry)].cells < rule.least_piece_cells;
  };
  std::size_t from = 0, to = walk.size();
  while (from < to && is_short(walk[from])) ++from;
  while (to > from && is_short(walk[to - 1])) --to;
  return {from, to};
}

}  // namespace

std::vector<Stroke> join_strokes(std::vector<Stroke> strokes, const JoinRule& rule) {
  if (strokes.size() < 2) return strokes;
  const std::vector<std::size_t> partner = choose_partners(stroke_ends(strokes, rule), rule);
  const auto joins = [&](std::size_t end) { return partner[end] != end; };
  std::vector<Stroke> joined;
  joined.reserve(strokes.size());  // grown stroke by stroke, it moved them 46 000 times a run
  std::vector<std::uint8_t> taken(strokes.size(), 0);
  std::vector<std::size_t> walk;  // the ends a joined stroke's pieces are entered at, in order
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    if (taken[s]) continue;
    // Walk back through the starts to the first piece, then forward through the pieces.
    std::size_t entry = 2 * s;  // the end the walk enters a piece at
    while (joins(entry)) entry = partner[entry] ^ 1u;
    walk.clear();
    while (true) {
      taken[stroke_of(entry)] = 1;
      walk.push_back(entry);
      const std::size_t exit = entry ^ 1u;
      if (!joins(exit)) break;
      entry = partner[exit];
    }
    const auto [from, to] = kept_span(walk, strokes, rule);
    if (from == to) continue;
    Stroke whole;
    for (std::size_t k = from; k < to; ++k)
      append_piece(whole, strokes[stroke_of(walk[k])], !is_start(walk[k]));
    joined.push_back(std::move(whole));
  }
  return joined;
}

struct StrokeGrouper::Index : EndIndex {
  using EndIndex::EndIndex;
};

StrokeGrouper::StrokeGrouper(const JoinRule& rule)
    : rule_(rule),
      angle_cos_(std::cos(rule.angle_deg * kPi / 180.0)),
      index_(std::make_unique<Index>(rule.gap, std::size_t{1} << 12)) {}

StrokeGrouper::~StrokeGrouper() = default;

std::size_t StrokeGrouper::add(const Stroke& stroke) {
  const AngleLimit limit{rule_.angle_deg, angle_cos_};
  const std::size_t id = first_held_ + records_.size();
  records_.push_back({id, kNone, id, stroke.chain.empty() ? 0 : stroke.chain.back().p, false, {}});
  const StrokeEnd ends[2] = {stroke_end(stroke.points, true, 2.0 * rule_.gap),
                             stroke_end(stroke.points, false, 2.0 * rule_.gap)};
  // The ends near both ends first, each one's record asked for at once: looked at one by one,
  // each record was a miss the next waited for (a sixth of add's time).
  near_.clear();
  std::size_t near_from[3] = {0, 0, 0};  // end e's near ends: [near_from[e], near_from[e + 1])
  for (int e = 0; e < 2; ++e) {
    index_->near(ends[e].at, [&](std::uint32_t other) {
      __builtin_prefetch(&record(stroke_of(other)));
      near_.push_back(other);
    });
    near_from[e + 1] = near_.size();
  }
  for (int e = 0; e < 2; ++e) {
    const StrokeEnd& end = ends[e];
    record(id).ends[e] = {end.at, end.dx, end.dy};
    for (std::size_t k = near_from[e]; k < near_from[e + 1]; ++k) {
      const std::uint32_t other = near_[k];
      const Record& r = record(stroke_of(other));
      const EndRecord& o = r.ends[other % 2];
      if (!r.taken && stroke_of(other) != id && may_join(end, {o.at, o.dx, o.dy}, rule_, limit))
        unite(id, stroke_of(other));
    }
    index_->insert(static_cast<std::uint32_t>(2 * id + static_cast<std::size_t>(e)), end.at);
  }
  return id;
}

void StrokeGrouper::prefetch(const Stroke& stroke) const {
  if (stroke.points.empty()) return;
  const void* slots[8];
  index_->near_slots(stroke.points.front(), slots);
  index_->near_slots(stroke.points.back(), slots + 4);
  // Here, not in a helper: GCC finds a helper that only prefetches pure and drops its calls.
  for (const void* slot : slots) __builtin_prefetch(slot);
}

void StrokeGrouper::unite(std::size_t a, std::size_t b) {
  a = group_of(a), b = group_of(b);
  if (a == b) return;
  if (b < a) std::swap(a, b);
  // The group's root is its first stroke; its members stay listed from there.
  Record &first = record(a), &second = record(b);
  second.parent = a;
  first.reach = std::max(first.reach, second.reach);
  record(first.tail).next = b;
  first.tail = second.tail;
}

std::size_t StrokeGrouper::group_of(std::size_t id) {
  while (record(id).parent != id) id = record(id).parent = record(record(id).parent).parent;
  return id;
}

void StrokeGrouper::take_group(std::size_t root, std::vector<std::size_t>& members) {
  members.clear();
  for (std::size_t m = root; m != kNone; m = record(m).next) members.push_back(m);
  if (members.size() > 1) std::sort(members.begin(), members.end());
  // Their ends stay in the index, passed over, until it is made anew (forget_before): taking
  // each out was a search of the table, long after the stroke was added, that missed the cache.
  for (std::size_t m : members) record(m).taken = true;
}

void StrokeGrouper::forget_before(std::size_t id) {
  // Groups are taken whole and named by their first strokes, so no stroke still held points to
  // one before `id`. The records go once they are most of those held, to move few.
  const std::size_t taken = std::min(id, first_held_ + records_.size()) - first_held_;
  if (taken < kForgetAtLeast || 2 * taken < records_.size()) return;
  records_.erase(records_.begin(), records_.begin() + static_cast<std::ptrdiff_t>(taken));
  first_held_ += taken;
  // The index, made anew of the ends of the strokes not taken.
  index_->clear(static_cast<std::uint32_t>(2 * first_held_));
  for (std::size_t k = 0; k < records_.size(); ++k) {
    if (records_[k].taken) continue;
    const auto first_end = static_cast<std::uint32_t>(2 * (first_held_ + k));
    index_->insert(first_end, records_[k].ends[0].at);
    index_->insert(first_end + 1, records_[k].ends[1].at);
  }
}

}  // namespace tsk
