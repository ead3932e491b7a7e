// The vector formats' numbers against printf's own "%.3f".
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "catch_compat.h"
#include "io/pages/fixed_number.h"

namespace {

std::string printed(double value) {
  char text[400];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

std::string appended(double value) {
  std::string out = "x";  // appended to what is there
  tsk::io::append_fixed3(out, value);
  return out.substr(1);
}

}  // namespace

TEST_CASE("numbers for vector art are written as printf writes them", "[preview]") {
  std::vector<double> values = {0.0,    -0.0,       0.0004, -0.0004,  0.0005, -0.0005, 0.0015,
                                1.0005, 2.5e-4,     0.9995, 999.9995, 1e9,    1e12,    -1e12,
                                1e15,   123456.789, 1e300,  -1e300,   5e-324, -5e-324};
  const double inf = std::numeric_limits<double>::infinity();
  values.insert(values.end(), {inf, -inf, std::numeric_limits<double>::quiet_NaN()});
  // Every number of thousandths and a half near where decimals tie, and near the fast path's
  // limit.
  for (int k = -4000; k <= 4000; ++k) values.push_back((k + 0.5) / 1000.0);
  for (int k = -50; k <= 50; ++k) {
    values.push_back(1e9 + k * 0.0005);
    values.push_back(std::nextafter(1e9, 2e9) + k * 0.0005);
  }
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> page(-100.0, 5000.0), exponent(-12.0, 18.0);
  for (int k = 0; k < 200000; ++k) {
    values.push_back(page(random));
    values.push_back((k % 2 ? -1.0 : 1.0) * std::pow(10.0, exponent(random)));
  }
  int differ = 0;
  for (double v : values) {
    if (appended(v) == printed(v)) continue;
    if (++differ <= 5) CHECK(appended(v) == printed(v));  // the first few, with their values
  }
  CHECK(differ == 0);
}
