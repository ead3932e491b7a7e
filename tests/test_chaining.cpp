#include <string>
#include <vector>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// Builds flags from one string per profile: 'o' occluding, 'h' hidden, 't' t-set, '.' valid.
CellFlags grid(const std::vector<std::string>& profiles) {
  CellFlags flags(profiles.size(), profiles[0].size());
  for (std::size_t p = 0; p < profiles.size(); ++p)
    for (std::size_t i = 0; i < profiles[p].size(); ++i) {
      const char ch = profiles[p][i];
      std::uint8_t f = ch == ' ' ? 0 : cell::valid;
      if (ch == 'o') f |= cell::occluding;
      if (ch == 'h') f |= cell::hidden;
      if (ch == 't') f |= cell::thinned;
      flags(p, i) = f;
    }
  return flags;
}

std::vector<std::pair<int, int>> cells(const Chain& chain) {
  std::vector<std::pair<int, int>> out;
  for (const ChainCell& c : chain) out.emplace_back(c.p, c.i);
  return out;
}

using Cells = std::vector<std::pair<int, int>>;

}  // namespace

TEST_CASE("factual chaining links overlapping hidden zones", "[chaining]") {
  // (0,1) with zone [1,3] overlaps (1,2) with [2,4], which overlaps (2,4) with [4,6].
  const auto chains = chain_factual(grid({".ohh.....", "..ohh....", "....ohh..", "........."}));
  REQUIRE(chains.size() == 1);
  CHECK(cells(chains[0]) == Cells{{0, 1}, {1, 2}, {2, 4}});
}

TEST_CASE("factual chaining prefers the nearest cell, ties to the front", "[chaining]") {
  // From (0, 4) with zone [4, 8]: candidates at 2 (zone to 4) and 6, gaps 2 and 2: pick 2.
  const auto chains = chain_factual(grid({"....ohhhh.", "..ohh.oh..", ".........."}));
  REQUIRE(chains.size() == 1);
  CHECK(cells(chains[0]) == Cells{{0, 4}, {1, 2}});
}

TEST_CASE("factual chaining skips used cells and never outputs one-cell chains", "[chaining]") {
  const auto chains = chain_factual(grid({".oh.oh.", ".oh....", "......o"}));
  // (0,1)-(1,1); (0,4) finds nothing unused overlapping; (2,6) is alone.
  REQUIRE(chains.size() == 1);
  CHECK(cells(chains[0]) == Cells{{0, 1}, {1, 1}});
}

TEST_CASE("factual chaining carries a zone across nodata", "[chaining]") {
  const auto chains = chain_factual(grid({".o  h....", "....o....", "........."}));
  REQUIRE(chains.size() == 1);
  CHECK(cells(chains[0]) == Cells{{0, 1}, {1, 4}});
}

TEST_CASE("formulated chaining links within the window, nearest first", "[chaining]") {
  const auto flags = grid({"...t......", "......t...", "..t....t..", "..t......."});
  // Window 4: from (1,6) both (2,2) (gap 4) and (2,7) (gap 1) qualify; the nearest wins.
  const auto wide = chain_formulated(flags, 4);
  REQUIRE(wide.size() == 2);
  CHECK(cells(wide[0]) == Cells{{0, 3}, {1, 6}, {2, 7}});
  CHECK(cells(wide[1]) == Cells{{2, 2}, {3, 2}});
  // Window 1: (0,3) is three cells from (1,6) and stays alone, so it is dropped.
  const auto narrow = chain_formulated(flags, 1);
  REQUIRE(narrow.size() == 2);
  CHECK(cells(narrow[0]) == Cells{{1, 6}, {2, 7}});
  CHECK(cells(narrow[1]) == Cells{{2, 2}, {3, 2}});
  const auto none = chain_formulated(flags, 0);
  REQUIRE(none.size() == 1);
  CHECK(cells(none[0]) == Cells{{2, 2}, {3, 2}});
}

TEST_CASE("every chained cell is used once and links neighbouring profiles", "[chaining]") {
  const HeightGrid z = test::random_terrain(80, 90, 3, 0.03);
  SilhouetteParams params;
  const SilhouetteResult r = test::run_on_dem(z, params);
  CellFlags seen(r.flags.rows(), r.flags.cols());
  for (const Stroke& s : r.strokes) {
    REQUIRE(s.chain.size() >= 3);
    for (std::size_t k = 0; k < s.chain.size(); ++k) {
      const ChainCell c = s.chain[k];
      const std::uint8_t need = s.cls == StrokeClass::factual ? cell::occluding : cell::thinned;
      REQUIRE((r.flags(c.p, c.i) & need));
      REQUIRE_FALSE(seen(c.p, c.i));
      seen(c.p, c.i) = 1;
      if (k > 0) {
        REQUIRE(c.p == s.chain[k - 1].p + 1);
        if (s.cls == StrokeClass::formulated) REQUIRE(std::abs(c.i - s.chain[k - 1].i) <= 3);
      }
    }
  }
}

namespace {

// The oracle: SPEC 1.7 taken literally on the flags, quadratic and simple. Each chain is grown
// to the right as far as it goes before the next unused cell (profiles left to right, cells
// front to back) starts one.
std::vector<Cells> scan_oracle(const CellFlags& flags, bool factual, int window) {
  const std::uint8_t bit = factual ? cell::occluding : cell::thinned;
  auto reach = [&](std::size_t p, std::size_t i) {  // end of the hidden zone behind (p, i)
    if (!factual) return i;
    std::size_t last = i;
    for (std::size_t j = i + 1; j < flags.cols(); ++j) {
      if (!(flags(p, j) & cell::valid)) continue;
      if (!(flags(p, j) & cell::hidden)) break;
      last = j;
    }
    return last;
  };
  CellFlags used(flags.rows(), flags.cols());
  std::vector<Cells> chains;
  for (std::size_t p = 0; p < flags.rows(); ++p)
    for (std::size_t i = 0; i < flags.cols(); ++i) {
      if (!(flags(p, i) & bit) || used(p, i)) continue;
      used(p, i) = 1;
      Cells chain{{static_cast<int>(p), static_cast<int>(i)}};
      std::size_t cp = p, ci = i;
      while (cp + 1 < flags.rows()) {
        const long lo = factual ? static_cast<long>(ci) : static_cast<long>(ci) - window;
        const long hi = factual ? static_cast<long>(reach(cp, ci)) : static_cast<long>(ci) + window;
        long best = -1, best_gap = 1L << 40;
        for (std::size_t j = 0; j < flags.cols(); ++j) {
          if (!(flags(cp + 1, j) & bit) || used(cp + 1, j)) continue;
          const long start = static_cast<long>(j), end = static_cast<long>(reach(cp + 1, j));
          if (end < lo || start > hi) continue;
          const long gap = std::labs(start - static_cast<long>(ci));
          if (gap < best_gap) best = start, best_gap = gap;
        }
        if (best < 0) break;
        ++cp, ci = static_cast<std::size_t>(best);
        used(cp, ci) = 1;
        chain.emplace_back(static_cast<int>(cp), static_cast<int>(ci));
      }
      if (chain.size() >= 2) chains.push_back(chain);
    }
  return chains;
}

}  // namespace

TEST_CASE("both chainers equal the literal scan of SPEC 1.7 on random terrains",
          "[chaining][oracle]") {
  for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    INFO("seed " << seed);
    const HeightGrid dem = test::random_terrain(40, 50, seed, 0.05);
    const SilhouetteResult r = test::run_on_dem(dem, SilhouetteParams{});
    for (bool factual : {true, false}) {
      const auto fast = factual ? chain_factual(r.flags) : chain_formulated(r.flags, 3);
      const auto slow = scan_oracle(r.flags, factual, 3);
      REQUIRE(fast.size() == slow.size());
      for (std::size_t k = 0; k < fast.size(); ++k) REQUIRE(cells(fast[k]) == slow[k]);
    }
  }
}

TEST_CASE("profile candidates equal a cell-by-cell reading of the flags", "[chaining][oracle]") {
  // Random flags, any bits, including hidden cells without the valid bit: the candidates and
  // hidden zones must be read as the rule says, cell by cell, from any first cell.
  std::mt19937 rng(11);
  ProfileCandidates got;  // reused, as the pipeline reuses it
  for (int round = 0; round < 800; ++round) {
    // Every other round, long hidden zones (as a panorama's), which are read eight cells at a time.
    const bool long_zones = round % 2 == 1;
    const std::size_t length = rng() % (long_zones ? 300 : 90);
    std::vector<std::uint8_t> f(length);
    for (std::uint8_t& v : f) {
      // Any bits, hidden, or valid: a hidden cell 3 times in 8, or 58 times in 64.
      const unsigned roll = rng() % (long_zones ? 64 : 8);
      const bool hidden = long_zones ? roll >= 6 : roll >= 3 && roll < 6;
      v = roll < 3 ? static_cast<std::uint8_t>(rng() % 64)
                   : static_cast<std::uint8_t>(cell::valid | (hidden ? cell::hidden : 0));
    }
    const std::size_t first = length ? rng() % (length + 1) : 0;
    for (bool factual : {true, false}) {
      INFO("round " << round << (factual ? " factual" : " formulated"));
      profile_candidates(f.data(), length, factual, got, first);  // over the last round's
      ProfileCandidates want;
      const std::uint8_t bit = factual ? cell::occluding : cell::thinned;
      bool in_zone = false;
      for (std::size_t i = first; i < length; ++i) {
        const bool valid = f[i] & cell::valid, hidden = f[i] & cell::hidden;
        if (in_zone && hidden) {
          want.reach.back() = static_cast<std::int32_t>(i);
          continue;
        }
        if (valid) in_zone = false;  // nodata carries a zone on
        if (f[i] & bit) {
          want.cell.push_back(static_cast<std::int32_t>(i));
          want.reach.push_back(static_cast<std::int32_t>(i));
          in_zone = factual;
        }
      }
      REQUIRE(got.cell == want.cell);
      REQUIRE(got.reach == want.reach);
    }
  }
}

TEST_CASE("the linker records the pairs of chains crossing in whose order decided a join",
          "[chaining][bands]") {
  const auto candidates = [](std::vector<std::int32_t> cells) {
    ProfileCandidates c;
    c.cell.assign(cells.begin(), cells.end());
    c.reach = c.cell;
    return c;
  };
  // Chains open at cells 2 and 6 of a profile (indices 0 and 1), in `order`, then the next
  // profile, formulated chains within `window` cells.
  const auto pairs = [&](std::vector<std::uint32_t> order, std::vector<std::int32_t> next,
                         int window) {
    ChainLinker linker(false, window);
    linker.start_from(candidates({2, 6}), order);
    linker.record_deciding_pairs();
    linker.add_profile(candidates(next));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const OrderPair& p : linker.deciding_pairs()) out.emplace_back(p.before, p.after);
    return out;
  };
  using Pairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
  // Both want cell 4: the older takes it, and the order decided the join.
  CHECK(pairs({0, 1}, {4}, 2) == Pairs{{0, 1}});
  CHECK(pairs({1, 0}, {4}, 2) == Pairs{{1, 0}});
  // Each has a cell of its own: no order decides anything.
  CHECK(pairs({0, 1}, {1, 7}, 2).empty());
  // The younger reaches the cell the older took, but has a nearer one: no pair.
  CHECK(pairs({0, 1}, {3, 6}, 3).empty());
  // Cells 4 and 8 are as near to 6, and the front one wins a tie: taken by the chain at 2, it
  // decided that the chain at 6 went to 8; taken first by the chain at 6, it closed the other.
  CHECK(pairs({0, 1}, {4, 8}, 2) == Pairs{{0, 1}});
  CHECK(pairs({1, 0}, {4, 8}, 2) == Pairs{{1, 0}});
  // Chains started later never compete before a chain crossing in: only crossing chains pair up.
  ChainLinker linker(false, 2);
  linker.start_from(candidates({2}), {0});
  linker.record_deciding_pairs();
  linker.add_profile(candidates({2, 10}));
  linker.add_profile(candidates({11}));
  CHECK(linker.deciding_pairs().empty());
}
