#include "whole_grid_stages.h"

#include <algorithm>

namespace tsk {
namespace {

// Calls stage(p) for every profile p of a grid of `profiles` rows, on `threads` threads.
template <typename Stage>
void every_profile(std::size_t profiles, unsigned threads, Stage stage) {
  parallel_for(profiles, threads, [&](std::size_t begin, std::size_t end) {
    for (std::size_t p = begin; p < end; ++p) stage(p);
  });
}

// Runs the linker over a whole classified grid and gathers the chains of two cells or more.
std::vector<Chain> link_grid(const CellFlags& flags, bool factual, int window) {
  ChainLinker linker(factual, window);
  std::vector<Chain> chains;
  ProfileCandidates candidates;
  for (std::size_t p = 0; p < flags.rows(); ++p) {
    profile_candidates(flags.row(p), flags.cols(), factual, candidates);
    const auto& joined = linker.add_profile(candidates);
    for (std::size_t k = 0; k < joined.size(); ++k) {
      if (joined[k].id >= chains.size()) chains.resize(joined[k].id + 1);
      chains[joined[k].id].push_back({static_cast<std::int32_t>(p), candidates.cell[k]});
    }
  }
  chains.erase(
      std::remove_if(chains.begin(), chains.end(), [](const Chain& c) { return c.size() < 2; }),
      chains.end());
  return chains;
}

}  // namespace

void select_candidates(const HeightGrid& z, double d, const ViewParams& view, CellFlags& flags,
                       unsigned threads) {
  every_profile(z.rows(), threads, [&](std::size_t p) {
    select_profile_candidates(z.row(p), flags.row(p), z.cols(), d, view);
  });
}

void apply_slope_filter(const HeightGrid& z, double d, double w, const FilterParams& filter,
                        CellFlags& flags, unsigned threads) {
  every_profile(z.rows(), threads, [&](std::size_t p) {
    filter_profile(profile_rows(z, p), flags.row(p), z.cols(), d, w, filter);
  });
}

void thin(CellFlags& flags, Placement placement, unsigned threads) {
  every_profile(flags.rows(), threads,
                [&](std::size_t p) { thin_profile(flags.row(p), flags.cols(), placement); });
}

std::vector<Chain> chain_factual(const CellFlags& flags) {
  return link_grid(flags, true, 0);
}

std::vector<Chain> chain_formulated(const CellFlags& flags, int window) {
  return link_grid(flags, false, window);
}

}  // namespace tsk
