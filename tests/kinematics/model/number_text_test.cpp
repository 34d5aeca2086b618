// Tests kinematics/model/number_text.h: shortest round-trip text (read back bit for bit), the
// folding of −0, non-finite spellings, short and fixed forms, and independence from the
// global C++ locale.

#include "kinematics/model/number_text.h"

#include "tests/support/catch.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <locale>
#include <random>
#include <sstream>
#include <string>

using namespace linkwright::kinematics;

namespace {

std::uint64_t bits(double value) { return std::bit_cast<std::uint64_t>(value); }

double parse(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  REQUIRE(end == text.c_str() + text.size());  // the whole text is one number
  return value;
}

// A numpunct that writes 1234.5 as "1.234,5", the way a German locale would.
struct CommaDecimal : std::numpunct<char> {
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

}  // namespace

TEST_CASE("formatDouble reads back to the same bits", "[number_text]") {
  const double values[] = {1.0,
                           -1.0,
                           0.1,
                           1.0 / 3.0,
                           2.0 / 3.0,
                           3.141592653589793,
                           70.0,
                           -0.5,
                           1e-300,
                           1e300,
                           5e-324,  // smallest subnormal
                           2.2250738585072014e-308,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::epsilon(),
                           123456789012345678.0,
                           1e21,
                           1e22,
                           29.999999999999996,
                           0.30000000000000004,
                           -1.2345678901234567e-7};
  for (const double v : values) {
    const std::string text = formatDouble(v);
    CAPTURE(text);
    CHECK(bits(parse(text)) == bits(v));
    CHECK(text.find(',') == std::string::npos);
  }
}

TEST_CASE("formatDouble round-trips random bit patterns", "[number_text]") {
  std::mt19937_64 rng(0x5eed1234u);
  int checked = 0;
  while (checked < 20000) {
    const double v = std::bit_cast<double>(rng());
    if (!std::isfinite(v) || v == 0.0) continue;
    const std::string text = formatDouble(v);
    if (bits(parse(text)) != bits(v)) FAIL("no round trip for " << text);
    ++checked;
  }
  SUCCEED("20000 random doubles read back exactly");
}

TEST_CASE("formatDouble is the shortest text, and never nan or inf", "[number_text]") {
  CHECK(formatDouble(70.0) == "70");
  CHECK(formatDouble(-70.0) == "-70");
  CHECK(formatDouble(0.1) == "0.1");
  CHECK(formatDouble(-0.5) == "-0.5");
  CHECK(formatDouble(1e-6) == "1e-06");
  CHECK(formatDouble(0.0) == "0");
  CHECK(formatDouble(-0.0) == "0");  // −0 reads as a sign that is not there
  // The last guard: a value that is not finite is an empty CSV cell, never "nan" or "inf".
  CHECK(formatDouble(std::numeric_limits<double>::quiet_NaN()).empty());
  CHECK(formatDouble(std::numeric_limits<double>::infinity()).empty());
  CHECK(formatDouble(-std::numeric_limits<double>::infinity()).empty());
}

TEST_CASE("the other writers spell a value that is not finite as null or undefined", "[number_text]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(formatJsonNumber(0.25) == "0.25");
  CHECK(formatJsonNumber(nan) == "null");
  CHECK(formatJsonNumber(-inf) == "null");
  CHECK(formatShort(inf) == "undefined");
  CHECK(formatNumber(nan) == "undefined");
  CHECK(formatNumber(-inf) == "undefined");
  CHECK(formatNumber(0.1) == "0.1");
  CHECK(formatNumber(-0.0) == "0");
  CHECK(formatNumber(1e160) == "1e+160");
  CHECK(formatShort(nan, 3) == "undefined");
  CHECK(formatFixed(-inf, 4) == "undefined");
  CHECK(formatFixed(nan, 2) == "undefined");
  // Every finite double has its fixed text, however long (the largest has 309 digits).
  const std::string big = formatFixed(1e60, 4);
  CHECK(big.find_first_not_of("0123456789.") == std::string::npos);
  CHECK(big.ends_with(".0000"));
  CHECK(std::strtod(big.c_str(), nullptr) == 1e60);
  CHECK(formatFixed(-1.7976931348623157e308, 2).size() == 1 + 309 + 3);
}

TEST_CASE("formatShort keeps the requested significant digits", "[number_text]") {
  CHECK(formatShort(115.0) == "115");
  CHECK(formatShort(1.0 / 3.0) == "0.333333");
  CHECK(formatShort(1e-6) == "1e-06");
  CHECK(formatShort(75.375473) == "75.3755");
  CHECK(formatShort(29.999999999999996, 12) == "30");
  CHECK(formatShort(180.00000000000003, 12) == "180");
  CHECK(formatShort(-0.0) == "0");
  CHECK(formatShort(2.0 / 3.0, 3) == "0.667");
  CHECK(formatShort(123456789.0) == "1.23457e+08");
}

TEST_CASE("formatFixed rounds to the given decimals and drops a lone minus", "[number_text]") {
  CHECK(formatFixed(25.2087, 2) == "25.21");
  CHECK(formatFixed(2.0 / 3.0, 3) == "0.667");
  CHECK(formatFixed(-1.5, 1) == "-1.5");
  CHECK(formatFixed(70.0, 2) == "70.00");
  CHECK(formatFixed(0.125, 2) == "0.12");  // exact tie: round half to even
  CHECK(formatFixed(1.005, 2) == "1.00");  // 1.005 is 1.00499999999999989… in binary
  CHECK(formatFixed(-0.001, 2) == "0.00");
  CHECK(formatFixed(-0.0, 2) == "0.00");
  CHECK(formatFixed(-0.4, 0) == "0");
  CHECK(formatFixed(-0.6, 0) == "-1");
  CHECK(formatFixed(-0.006, 2) == "-0.01");
  CHECK(formatFixed(1e6, 1) == "1000000.0");
}

TEST_CASE("Number formatting ignores the global C++ locale", "[number_text]") {
  const std::locale previous = std::locale::global(std::locale(std::locale::classic(), new CommaDecimal));
  // The facet is live: a stream in the global locale now writes a decimal comma.
  std::ostringstream probe;
  probe << 1234.5;
  const std::string probed = probe.str();
  const std::string shortest = formatDouble(1234.5);
  const std::string rounded = formatShort(1234.5);
  const std::string fixed = formatFixed(1234.5, 2);
  std::locale::global(previous);
  CHECK(probed == "1.234,5");
  CHECK(shortest == "1234.5");
  CHECK(rounded == "1234.5");
  CHECK(fixed == "1234.50");
}
