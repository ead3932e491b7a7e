#include <random>
#include <string>
#include <vector>

#include "catch_compat.h"
#include "test_support.h"

using namespace tsk;

namespace {

// A profile written as letters: '.' valid, 'f' f-set, 'o' occluding, ' ' nodata.
std::vector<std::uint8_t> profile(const std::string& cells) {
  std::vector<std::uint8_t> flags;
  for (char ch : cells) {
    std::uint8_t f = ch == ' ' ? 0 : cell::valid;
    if (ch == 'f') f |= cell::candidate | cell::filtered;
    if (ch == 'o') f |= cell::occluding;
    flags.push_back(f);
  }
  return flags;
}

// The thinned cells as a string: 't' where kept, '.' elsewhere.
std::string thinned(std::vector<std::uint8_t> flags, Placement placement = Placement::far) {
  thin_profile(flags.data(), flags.size(), placement);
  std::string out;
  for (std::uint8_t f : flags) out += (f & cell::thinned) ? 't' : '.';
  return out;
}

}  // namespace

TEST_CASE("rule (b): a zone keeps its cell furthest from the viewer", "[thinning]") {
  CHECK(thinned(profile("..fff...")) == "....t...");
  CHECK(thinned(profile("f.ff.fff")) == "t..t...t");  // a zone at the far end is kept too
}

TEST_CASE("rule (a): a zone leading up to a Factual Silhouette is dropped", "[thinning]") {
  CHECK(thinned(profile("..fffo..")) == "........");
  CHECK(thinned(profile("..fff...")) == "....t...");  // not touching: kept
}

TEST_CASE("nodata breaks a zone", "[thinning]") {
  CHECK(thinned(profile("ff ff.")) == ".t..t.");
}

TEST_CASE("near_and_far placement keeps both ends", "[thinning]") {
  CHECK(thinned(profile(".ffff."), Placement::near_and_far) == ".t..t.");
  CHECK(thinned(profile(".f.."), Placement::near_and_far) == ".t..");
  CHECK(thinned(profile(".fffo"), Placement::near_and_far) == ".....");
}

TEST_CASE("whole-grid thinning equals the per-profile rule", "[thinning]") {
  CellFlags grid(2, 6);
  const auto a = profile("ff.fo.");
  const auto b = profile(".fff..");
  std::copy(a.begin(), a.end(), grid.row(0));
  std::copy(b.begin(), b.end(), grid.row(1));
  thin(grid, Placement::far, 2);
  std::string out;
  for (std::size_t p = 0; p < 2; ++p)
    for (std::size_t i = 0; i < 6; ++i) out += (grid(p, i) & cell::thinned) ? 't' : '.';
  CHECK(out == ".t.......t..");
}

namespace {

// SPEC 1.6 written out zone by zone, for comparison: each maximal run of f-set cells is dropped
// when the cell behind its last is occluding, else its last cell (and for near_and_far its first)
// is kept.
std::vector<std::uint8_t> thinned_by_zones(std::vector<std::uint8_t> flags, Placement placement) {
  std::size_t i = 0;
  while (i < flags.size()) {
    if (!(flags[i] & cell::filtered)) {
      ++i;
      continue;
    }
    std::size_t last = i;
    while (last + 1 < flags.size() && (flags[last + 1] & cell::filtered)) ++last;
    const bool dropped = last + 1 < flags.size() && (flags[last + 1] & cell::occluding);
    if (!dropped) {
      flags[last] |= cell::thinned;
      if (placement == Placement::near_and_far) flags[i] |= cell::thinned;
    }
    i = last + 1;
  }
  return flags;
}

}  // namespace

TEST_CASE("thinning equals the rule written zone by zone on random profiles", "[thinning]") {
  std::mt19937 random(20261206);
  // Profiles of every length up to past a few vector widths, f-set shares from sparse to full.
  for (std::size_t length = 0; length <= 70; ++length) {
    for (int share_pct : {5, 40, 80, 100}) {
      std::uniform_int_distribution<int> pct(0, 99);
      std::vector<std::uint8_t> flags(length);
      for (std::uint8_t& f : flags) {
        f = pct(random) < 90 ? cell::valid : 0;
        if (f && pct(random) < share_pct) f |= cell::candidate | cell::filtered;
        // Occluding cells, some of them in the f-set too: the rule asks only whether the cell
        // behind a zone is occluding.
        if (f && pct(random) < 15) f |= cell::occluding;
      }
      for (Placement placement : {Placement::far, Placement::near_and_far}) {
        std::vector<std::uint8_t> thinned_flags = flags;
        thin_profile(thinned_flags.data(), thinned_flags.size(), placement);
        CHECK(thinned_flags == thinned_by_zones(flags, placement));
      }
    }
  }
}
