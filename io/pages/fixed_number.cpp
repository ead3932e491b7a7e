#include "io/pages/fixed_number.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>

#include "core/base/errors.h"

namespace tsk::io {
namespace {

// Below this many thousandths, value * 1000 is within 1e-4 of its exact product (a double's
// relative error is at most 2^-53), so its rounding is the exact value's unless the product lies
// within kTieMargin of a half.
constexpr double kFastLimit = 1e12;
constexpr double kTieMargin = 1e-3;

// The exact rounding, at full cost. The text of any double fits: 309 digits, its sign, the point
// and three decimals.
void append_exact(std::string& out, double value) {
  char text[320];
  const auto [end, error] =
      std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, 3);
  if (error != std::errc()) throw Error("internal: a number did not fit its text");
  out.append(text, end);
}

}  // namespace

void append_fixed3(std::string& out, double value) {
  const double thousandths = std::fabs(value) * 1000.0;
  if (!(thousandths < kFastLimit)) {  // large, infinite or NaN
    append_exact(out, value);
    return;
  }
  const double whole = std::floor(thousandths);
  const double fraction = thousandths - whole;
  if (std::fabs(fraction - 0.5) < kTieMargin) {  // near a tie: the exact value decides
    append_exact(out, value);
    return;
  }
  const auto rounded = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1u : 0u);
  char text[32];
  char* end = text + sizeof text;
  char* at = end;
  std::uint64_t rest = rounded;
  for (int digit = 0; digit < 3; ++digit, rest /= 10) *--at = static_cast<char>('0' + rest % 10);
  *--at = '.';
  do {
    *--at = static_cast<char>('0' + rest % 10);
    rest /= 10;
  } while (rest > 0);
  if (std::signbit(value)) *--at = '-';
  out.append(at, end);
}

}  // namespace tsk::io
