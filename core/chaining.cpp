#include "chaining.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace tsk {
namespace {

// The cells of one profile that may join chains, in front-to-back order. For factual chaining
// `reach` is the last cell of the hidden zone; for formulated chaining it equals the cell.
struct ProfileCells {
  std::vector<std::int32_t> cell;
  std::vector<std::int32_t> reach;
  std::vector<std::uint8_t> used;
};

std::vector<ProfileCells> collect(const CellFlags& flags, std::uint8_t bit, unsigned threads,
                                  const ProgressFn& progress) {
  std::vector<ProfileCells> profiles(flags.rows());
  const std::size_t length = flags.cols();
  parallel_for(
      flags.rows(), threads,
      [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
          const std::uint8_t* f = flags.row(p);
          ProfileCells& out = profiles[p];
          bool in_zone = false;  // after an occluding cell, until the next visible valid cell
          for (std::size_t i = 0; i < length; ++i) {
            const auto index = static_cast<std::int32_t>(i);
            if (bit == cell::occluding && in_zone && (f[i] & cell::hidden)) {
              out.reach.back() = index;
              continue;
            }
            if (f[i] & cell::valid) in_zone = false;
            if (f[i] & bit) {
              out.cell.push_back(index);
              out.reach.push_back(index);
              in_zone = bit == cell::occluding;
            }
          }
          out.used.assign(out.cell.size(), 0);
        }
      },
      progress);
  return profiles;
}

// Index into `next` of the unused cell with the smallest |cell - i| among those whose
// [cell, reach] overlaps [lo, hi]; ties go to the smaller cell. -1 if none.
std::ptrdiff_t nearest_overlapping(const ProfileCells& next, std::int32_t i, std::int32_t lo,
                                   std::int32_t hi) {
  // Intervals on a profile are disjoint and sorted, so reach is sorted too.
  auto first = std::lower_bound(next.reach.begin(), next.reach.end(), lo);
  std::ptrdiff_t best = -1;
  std::int64_t best_gap = std::numeric_limits<std::int64_t>::max();
  for (auto k = first - next.reach.begin(); k < static_cast<std::ptrdiff_t>(next.cell.size());
       ++k) {
    const std::int32_t j = next.cell[static_cast<std::size_t>(k)];
    if (j > hi) break;
    if (next.used[static_cast<std::size_t>(k)]) continue;
    const std::int64_t gap = std::llabs(static_cast<std::int64_t>(j) - i);
    if (gap < best_gap) {  // strict: on a tie the earlier (smaller j) stays
      best_gap = gap;
      best = k;
    }
  }
  return best;
}

// Scans profiles left to right and cells front to back, growing each chain to the right.
std::vector<Chain> link(std::vector<ProfileCells>& profiles, bool factual, int window) {
  std::vector<Chain> chains;
  Chain chain;
  for (std::size_t p = 0; p < profiles.size(); ++p) {
    for (std::size_t k = 0; k < profiles[p].cell.size(); ++k) {
      if (profiles[p].used[k]) continue;
      profiles[p].used[k] = 1;
      chain.clear();
      std::size_t cur_p = p;
      std::size_t cur_k = k;
      chain.push_back({static_cast<std::int32_t>(p), profiles[p].cell[k]});
      while (cur_p + 1 < profiles.size()) {
        const std::int32_t i = profiles[cur_p].cell[cur_k];
        const std::int32_t lo = factual ? i : i - window;
        const std::int32_t hi = factual ? profiles[cur_p].reach[cur_k] : i + window;
        const std::ptrdiff_t found = nearest_overlapping(profiles[cur_p + 1], i, lo, hi);
        if (found < 0) break;
        ++cur_p;
        cur_k = static_cast<std::size_t>(found);
        profiles[cur_p].used[cur_k] = 1;
        chain.push_back({static_cast<std::int32_t>(cur_p), profiles[cur_p].cell[cur_k]});
      }
      if (chain.size() >= 2) chains.push_back(chain);
    }
  }
  return chains;
}

}  // namespace

std::vector<Chain> chain_factual(const CellFlags& flags, unsigned threads,
                                 const ProgressFn& progress) {
  auto profiles = collect(flags, cell::occluding, threads, progress);
  return link(profiles, true, 0);
}

std::vector<Chain> chain_formulated(const CellFlags& flags, int window, unsigned threads,
                                    const ProgressFn& progress) {
  auto profiles = collect(flags, cell::thinned, threads, progress);
  return link(profiles, false, window);
}

}  // namespace tsk
