#include "core/method/chaining.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "core/base/errors.h"

namespace tsk {
namespace {

// Index of the candidate of `next`, from index `from` on, not yet in `used` with the smallest
// |cell - i| among those whose [cell, reach] overlaps [lo, hi]; ties go to the smaller cell. -1 if
// none. `from` is the first candidate whose reach is at least lo.
std::ptrdiff_t nearest_overlapping(const ProfileCandidates& next,
                                   const std::vector<std::uint8_t>& used, std::size_t from,
                                   std::int32_t i, std::int32_t hi) {
  std::ptrdiff_t best = -1;
  std::int64_t best_gap = std::numeric_limits<std::int64_t>::max();
  for (std::size_t k = from; k < next.cell.size(); ++k) {
    const std::int32_t j = next.cell[k];
    if (j > hi) break;
    if (used[k]) continue;
    const std::int64_t gap = std::llabs(static_cast<std::int64_t>(j) - i);
    if (gap < best_gap) {  // strict: on a tie the earlier (smaller j) stays
      best_gap = gap;
      best = static_cast<std::ptrdiff_t>(k);
    }
  }
  return best;
}

constexpr std::size_t kNoCell = static_cast<std::size_t>(-1);

// From cell i on, up to the next cell that is visible (valid and not hidden): the last hidden cell,
// or kNoCell when none is; i is left at that visible cell (or `length`). Eight cells at a time
// where the bytes are read in order: a panorama's hidden zones run thousands of samples.
std::size_t last_hidden_before_visible(const std::uint8_t* f, std::size_t& i, std::size_t length) {
  std::size_t last_hidden = kNoCell;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  constexpr std::uint64_t kLowBits = 0x0101010101010101ull;
  for (std::uint64_t word; i + 8 <= length; i += 8) {
    std::memcpy(&word, f + i, sizeof word);
    const std::uint64_t hidden = (word >> 1) & kLowBits;  // cell::hidden
    // cell::valid or cell::occluding (a visible cell with data), not hidden
    const std::uint64_t visible = (word | (word >> 2)) & kLowBits & ~hidden;
    // The bytes before the first visible one (all eight when none is).
    const std::uint64_t before = visible ? (visible & (~visible + 1)) - 1 : ~std::uint64_t{0};
    if (const std::uint64_t zone = hidden & before)
      last_hidden = i + static_cast<std::size_t>(63 - __builtin_clzll(zone)) / 8;
    if (visible) {
      i += static_cast<std::size_t>(__builtin_ctzll(visible)) / 8;
      return last_hidden;
    }
  }
#endif
  for (; i < length; ++i) {
    if (f[i] & cell::hidden) {
      last_hidden = i;
    } else if (f[i] & (cell::valid | cell::occluding)) {
      break;
    }
  }
  return last_hidden;
}

// The t-set cells among [first, length), as indices into `cells`. Eight cells without one are
// passed over at once (a steep DEM's t-set is sparse); the others are sifted (a low-relief DEM's
// t-set is a sixth of its cells).
void sift_thinned(const std::uint8_t* f, std::size_t first, std::size_t length,
                  ScratchVector<std::int32_t>& cells) {
  cells.resize(length - std::min(first, length));
  std::int32_t* out = cells.data();
  std::size_t count = 0;
  constexpr std::uint64_t kInAnyByte = 0x0101010101010101ull * cell::thinned;
  std::size_t i = first;
  for (std::uint64_t word; i + 8 <= length; i += 8) {
    std::memcpy(&word, f + i, sizeof word);
    if (word & kInAnyByte)
      count += sift_cells(f, i, i + 8, cell::thinned, cell::thinned, 0, out + count);
  }
  count += sift_cells(f, i, length, cell::thinned, cell::thinned, 0, out + count);
  cells.resize(count);
}

}  // namespace

void profile_candidates(const std::uint8_t* f, std::size_t length, bool factual,
                        ProfileCandidates& out, std::size_t first) {
  if (!factual) {
    sift_thinned(f, first, length, out.cell);
    out.reach.assign(out.cell.begin(), out.cell.end());
    return;
  }
  const std::uint8_t bit = cell::occluding;
  out.cell.clear();
  out.reach.clear();
  for (std::size_t i = next_cell_with(f, first, length, bit); i < length;
       i = next_cell_with(f, i, length, bit)) {
    const auto index = static_cast<std::int32_t>(i);
    out.cell.push_back(index);
    out.reach.push_back(index);
    ++i;
    // The hidden zone: hidden cells, and nodata between them, up to the next visible cell.
    const std::size_t last_hidden = last_hidden_before_visible(f, i, length);
    if (last_hidden != kNoCell) out.reach.back() = static_cast<std::int32_t>(last_hidden);
  }
}

ChainLinker::ChainLinker(bool factual, int window) : factual_(factual), window_(window) {}

std::uint32_t ChainLinker::take_slot() {
  if (free_slots_.empty()) return slot_count_++;
  const std::uint32_t slot = free_slots_.back();
  free_slots_.pop_back();
  return slot;
}

const std::vector<ChainRef>& ChainLinker::add_profile(const ProfileCandidates& next) {
  for (const ChainRef& c : closed_) free_slots_.push_back(c.slot);
  used_.assign(next.cell.size(), 0);
  joined_.assign(next.cell.size(), ChainRef{0, 0});
  closed_.clear();
  still_open_.clear();
  // Where each last cell's search starts in `next`: the first candidate reaching its low end.
  // Both profiles are sorted and so are the low ends, so one merge finds them all.
  const auto low_end = [this](std::size_t k) {
    return factual_ ? last_.cell[k] : last_.cell[k] - window_;
  };
  search_from_.resize(last_.cell.size());
  for (std::size_t k = 0, from = 0; k < last_.cell.size(); ++k) {
    while (from < next.reach.size() && next.reach[from] < low_end(k)) ++from;
    search_from_[k] = from;
  }
  for (const Open& o : open_) {
    const std::int32_t i = last_.cell[o.k];
    const std::int32_t hi = factual_ ? last_.reach[o.k] : i + window_;
    const std::ptrdiff_t found = nearest_overlapping(next, used_, search_from_[o.k], i, hi);
    if (o.chain.id < crossing_end_) note_deciding_claims(next, o, hi, found);
    if (found < 0) {
      closed_.push_back(o.chain);
      continue;
    }
    const auto k = static_cast<std::size_t>(found);
    used_[k] = 1;
    joined_[k] = o.chain;
    still_open_.push_back({o.chain, k});
  }
  for (std::size_t k = 0; k < next.cell.size(); ++k) {
    if (used_[k]) continue;
    joined_[k] = ChainRef{started_++, take_slot()};
    still_open_.push_back({joined_[k], k});
  }
  std::swap(open_, still_open_);
  last_.cell.assign(next.cell.begin(), next.cell.end());  // into storage of its own, reused
  last_.reach.assign(next.reach.begin(), next.reach.end());
  return joined_;
}

void ChainLinker::start_from(const ProfileCandidates& last,
                             const std::vector<std::uint32_t>& order) {
  if (order.size() != last.cell.size())
    throw Error("a band's chain order does not fit its profile");
  std::vector<std::uint8_t> seen(order.size(), 0);
  open_.clear();
  for (const std::uint32_t k : order) {
    if (k >= order.size() || seen[k]) throw Error("a band's chain order does not fit its profile");
    seen[k] = 1;
    open_.push_back({ChainRef{started_++, take_slot()}, k});
  }
  closed_.clear();
  last_.cell.assign(last.cell.begin(), last.cell.end());
  last_.reach.assign(last.reach.begin(), last.reach.end());
}

void ChainLinker::record_deciding_pairs() {
  crossing_end_ = started_;
  crossing_ids_.clear();
  crossing_cells_.clear();
  deciding_.clear();
  // Open chains keep the order they were started in, so their ids rise.
  for (const Open& o : open_) {
    crossing_ids_.push_back(o.chain.id);
    crossing_cells_.push_back(static_cast<std::uint32_t>(o.k));
  }
}

std::uint32_t ChainLinker::crossing_cell(std::size_t id) const {
  const auto at = std::lower_bound(crossing_ids_.begin(), crossing_ids_.end(), id);
  if (at == crossing_ids_.end() || *at != id) throw Error("a chain crossing in was not recorded");
  return crossing_cells_[static_cast<std::size_t>(at - crossing_ids_.begin())];
}

void ChainLinker::note_deciding_claims(const ProfileCandidates& next, const Open& o,
                                       std::int32_t hi, std::ptrdiff_t found) {
  const std::int32_t i = last_.cell[o.k];
  const auto gap = [&](std::size_t k) {
    return std::llabs(static_cast<std::int64_t>(next.cell[k]) - i);
  };
  // As nearest_overlapping searches: the nearest wins, ties to the earlier.
  for (std::size_t k = search_from_[o.k]; k < next.cell.size() && next.cell[k] <= hi; ++k) {
    if (!used_[k] || joined_[k].id >= crossing_end_) continue;
    if (found >= 0) {
      const auto f = static_cast<std::size_t>(found);
      if (gap(k) > gap(f) || (gap(k) == gap(f) && k > f)) continue;
    }
    deciding_.push_back({crossing_cell(joined_[k].id), crossing_cell(o.chain.id)});
  }
}

std::vector<OrderPair> ChainLinker::deciding_pairs() const {
  std::vector<OrderPair> pairs = deciding_;
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

const std::vector<ChainRef>& ChainLinker::close_all() {
  for (const ChainRef& c : closed_) free_slots_.push_back(c.slot);
  closed_.clear();
  for (const Open& o : open_) closed_.push_back(o.chain);
  open_.clear();
  return closed_;
}

}  // namespace tsk
