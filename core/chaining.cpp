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

// Links profiles one at a time, left to right. This equals the scan of SPEC 1.7 (each chain grown
// fully to the right before the next unused cell, front to back, starts one): in every new
// profile the open chains pick their cell in the order they were started, then the cells left
// unused start new chains front to back. Needs only two profiles at a time.
class StreamingLinker {
 public:
  StreamingLinker(bool factual, int window) : factual_(factual), window_(window) {}

  void add_profile(ProfileCells&& next, std::int32_t p) {
    std::vector<Open> still_open;
    for (Open& o : open_) {
      const std::int32_t i = last_.cell[o.k];
      const std::int32_t lo = factual_ ? i : i - window_;
      const std::int32_t hi = factual_ ? last_.reach[o.k] : i + window_;
      const std::ptrdiff_t found = nearest_overlapping(next, i, lo, hi);
      if (found < 0) {
        close(std::move(o));
        continue;
      }
      o.k = static_cast<std::size_t>(found);
      next.used[o.k] = 1;
      o.chain.push_back({p, next.cell[o.k]});
      still_open.push_back(std::move(o));
    }
    for (std::size_t k = 0; k < next.cell.size(); ++k) {
      if (next.used[k]) continue;
      next.used[k] = 1;
      still_open.push_back({Chain{{p, next.cell[k]}}, k, started_++});
    }
    open_ = std::move(still_open);
    last_ = std::move(next);
  }

  // The chains of two cells or more, in the order they were started.
  std::vector<Chain> finish() {
    for (Open& o : open_) close(std::move(o));
    open_.clear();
    std::sort(done_.begin(), done_.end(),
              [](const Open& a, const Open& b) { return a.order < b.order; });
    std::vector<Chain> chains;
    chains.reserve(done_.size());
    for (Open& o : done_) chains.push_back(std::move(o.chain));
    return chains;
  }

 private:
  struct Open {
    Chain chain;
    std::size_t k;      // index of the chain's last cell in the last profile
    std::size_t order;  // when it was started
  };

  void close(Open&& o) {
    if (o.chain.size() >= 2) done_.push_back(std::move(o));
  }

  bool factual_;
  int window_;
  ProfileCells last_;
  std::vector<Open> open_, done_;
  std::size_t started_ = 0;
};

std::vector<Chain> link(std::vector<ProfileCells>& profiles, bool factual, int window) {
  StreamingLinker linker(factual, window);
  for (std::size_t p = 0; p < profiles.size(); ++p) {
    linker.add_profile(std::move(profiles[p]), static_cast<std::int32_t>(p));
  }
  return linker.finish();
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
