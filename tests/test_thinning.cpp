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
