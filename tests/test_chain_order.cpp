#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "catch_compat.h"
#include "core/base/errors.h"
#include "core/method/chain_order.h"

using namespace tsk;

namespace {

// A stroke that says which chain and piece it was held for.
Stroke tagged(std::size_t chain, std::size_t piece) {
  Stroke s;
  s.cells = static_cast<int>(piece);
  s.mean_z = static_cast<double>(chain);
  s.points.assign(piece + 1, StrokePoint{static_cast<double>(chain), 0.0});
  return s;
}

using Key = std::pair<std::size_t, std::size_t>;  // chain, piece

// Chains open in order and close at random, as a linker's do: a closing chain holds 0 to 3
// pieces, then everything before the oldest chain still open is handed on. The oracle is a
// sorted set of what is held, emptied of keys before that chain.
void run_random_scan(std::uint32_t seed, std::size_t chains, std::size_t most_open) {
  std::mt19937 random(seed);
  ChainOrder order;
  std::set<Key> held;
  std::vector<std::size_t> open;  // ascending
  std::vector<Key> handed, expected;
  std::size_t started = 0;
  while (started < chains || !open.empty()) {
    const bool start =
        started < chains && (open.empty() || (open.size() < most_open && random() % 3 != 0));
    if (start) {
      open.push_back(started++);
      continue;
    }
    // Close one open chain at random; the oldest one less often, so that many are held.
    const std::size_t at = open.size() == 1 ? 0 : 1 + random() % (open.size() - 1);
    const std::size_t chain = open[random() % 8 == 0 ? 0 : at];
    open.erase(std::find(open.begin(), open.end(), chain));
    const std::size_t pieces = random() % 4;
    for (std::size_t k = 0; k < pieces; ++k) {
      order.hold(chain, k, tagged(chain, k));
      held.insert({chain, k});
    }
    const std::size_t oldest = open.empty() ? started : open.front();
    order.release_before(oldest, [&](Stroke&& s) {
      handed.push_back({static_cast<std::size_t>(s.mean_z), static_cast<std::size_t>(s.cells)});
      REQUIRE(s.points.size() == static_cast<std::size_t>(s.cells) + 1);
    });
    while (!held.empty() && held.begin()->first < oldest) {
      expected.push_back(*held.begin());
      held.erase(held.begin());
    }
    REQUIRE(handed == expected);
  }
  REQUIRE(held.empty());
  REQUIRE(expected.size() > chains / 2);
}

}  // namespace

TEST_CASE("chain order hands strokes on as a sorted set of those held does", "[strokes]") {
  run_random_scan(1, 200, 5);
  run_random_scan(2, 20000, 50);    // many held at once, the table forgotten and reused
  run_random_scan(3, 20000, 3000);  // chains open long, across forgettings
}

TEST_CASE("chain order refuses strokes out of the scan's order", "[strokes]") {
  ChainOrder order;
  REQUIRE_THROWS_AS(order.hold(0, 1, tagged(0, 1)), Error);  // a piece before any piece 0
  order.hold(0, 0, tagged(0, 0));
  order.hold(3, 0, tagged(3, 0));
  REQUIRE_THROWS_AS(order.hold(2, 1, tagged(2, 1)), Error);  // not after its piece 0
  REQUIRE_THROWS_AS(order.hold(0, 0, tagged(0, 0)), Error);  // twice
  std::vector<std::size_t> chains;
  order.release_before(2,
                       [&](Stroke&& s) { chains.push_back(static_cast<std::size_t>(s.mean_z)); });
  REQUIRE(chains == std::vector<std::size_t>{0});
  REQUIRE_THROWS_AS(order.hold(1, 0, tagged(1, 0)), Error);  // handed on already
  order.release_before(10,
                       [&](Stroke&& s) { chains.push_back(static_cast<std::size_t>(s.mean_z)); });
  REQUIRE(chains == std::vector<std::size_t>{0, 3});
}

TEST_CASE("chain order hands the last strokes on in runs, each settling at the least profile left",
          "[strokes]") {
  // Chains whose first profiles go up and down (a long chain may start before younger ones), some
  // with a piece of no cells; the oracle is the least first profile of every piece handed on
  // after a settling, by brute force.
  for (const std::size_t per_run : {1, 3, 7, 64, 1000}) {
    CAPTURE(per_run);
    std::mt19937 random(static_cast<std::uint32_t>(per_run));
    ChainOrder order;
    order.hold(0, 0, tagged(0, 0));
    order.release_before(1, [](Stroke&&) {});  // the table starts after chain 0
    std::vector<Key> held;
    for (std::size_t chain = 1; chain < 200; ++chain) {
      if (random() % 5 == 0) continue;  // a chain dropped: shorter than any stroke
      auto profile = static_cast<std::int32_t>(random() % 50);
      for (std::size_t piece = 0; piece <= random() % 3; ++piece) {
        Stroke s = tagged(chain, piece);
        if (random() % 11 != 0) s.chain = {{profile, 0}, {profile + 1, 0}};
        profile += 2 + static_cast<std::int32_t>(random() % 4);  // the next piece starts later
        order.hold(chain, piece, std::move(s));
        held.push_back({chain, piece});
      }
    }
    std::vector<Key> handed;
    std::vector<double> first_profiles;                   // of the pieces handed on, in order
    std::vector<std::pair<std::size_t, double>> settled;  // pieces handed on before, frontier
    order.release_all_in_runs(
        per_run,
        [&](Stroke&& s) {
          handed.push_back({static_cast<std::size_t>(s.mean_z), static_cast<std::size_t>(s.cells)});
          first_profiles.push_back(s.chain.empty() ? -std::numeric_limits<double>::infinity()
                                                   : static_cast<double>(s.chain.front().p));
        },
        [&](double frontier) { settled.emplace_back(handed.size(), frontier); });
    REQUIRE(handed == held);
    std::set<std::size_t> chains;
    for (const Key& k : held) chains.insert(k.first);
    REQUIRE(settled.size() == (chains.size() - 1) / per_run);
    for (const auto& [before, frontier] : settled) {
      CAPTURE(before);
      REQUIRE(before < handed.size());
      CHECK(frontier == *std::min_element(first_profiles.begin() + static_cast<long>(before),
                                          first_profiles.end()));
      // A settling comes between chains, after a whole run of them.
      CHECK(handed[before].second == 0);
    }
  }
}
