// Catch2 2 (Debian 12) and Catch2 3 (Debian 13 and later) behind one include. The tests are
// written with Catch2 2's names; under Catch2 3 these name its matchers and Approx.
#pragma once

#if __has_include(<catch2/catch_test_macros.hpp>)
// What the tests use, rather than catch_all.hpp: its benchmark headers overwhelm GCC's column
// tracking in the larger test files.
#include <catch2/catch_approx.hpp>
#include <catch2/catch_session.hpp>
#include <catch2/catch_test_macros.hpp>
#include <catch2/generators/catch_generators.hpp>
#include <catch2/matchers/catch_matchers_string.hpp>
#include <string>

using Catch::Approx;

namespace Catch {
inline Matchers::StringContainsMatcher Contains(const std::string& text,
                                                CaseSensitive sensitive = CaseSensitive::Yes) {
  return Matchers::ContainsSubstring(text, sensitive);
}
using Matchers::EndsWith;
using Matchers::StartsWith;
}  // namespace Catch
#else
#include <catch2/catch.hpp>
#endif
