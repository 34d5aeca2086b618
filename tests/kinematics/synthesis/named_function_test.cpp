// The named functions of function generation (synthesis/named_function.h): each one's value,
// and every range where one is undefined or infinite refused naming x0 or x1, never a NaN.

#include "kinematics/synthesis/named_function.h"

#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>
#include <string>
#include <tuple>

using namespace linkwright::kinematics;

TEST_CASE("Named functions: each by its name, with its value", "[synthesis][function]") {
  CHECK(namedFunctions().size() == 10);
  const auto at = [](const char* name, double x) {
    const NamedFunction* f = findNamedFunction(name);
    REQUIRE(f != nullptr);
    return f->f(x);
  };
  CHECK(at("log10", 1000.0) == Approx(3.0));
  CHECK(at("ln", std::exp(2.0)) == Approx(2.0));
  CHECK(at("exp", 0.0) == 1.0);
  CHECK(at("sqrt", 9.0) == 3.0);
  CHECK(at("square", -3.0) == 9.0);
  CHECK(at("cube", -2.0) == -8.0);
  CHECK(at("reciprocal", 4.0) == 0.25);
  CHECK(at("sin", kPi / 2.0) == 1.0);
  CHECK(at("cos", 0.0) == 1.0);
  CHECK(at("tan", kPi / 4.0) == Approx(1.0));
  CHECK(findNamedFunction("log") == nullptr);
}

TEST_CASE("Named functions refuse ranges where they are undefined, naming the field", "[synthesis][function][errors]") {
  const auto refused = [](const char* name, double x0, double x1, const char* field, const std::string& text) {
    INFO(name << " on [" << x0 << ", " << x1 << "]");
    const auto e = checkFunctionRange(*findNamedFunction(name), x0, x1);
    REQUIRE(e.has_value());
    CHECK(e->field == field);
    CHECK(e->message == text);
  };
  refused("log10", 0.0, 10.0, "x0", "log10 needs x > 0 over the range (got [0, 10])");
  refused("ln", -1.0, 1.0, "x0", "ln needs x > 0 over the range (got [-1, 1])");
  refused("sqrt", -0.5, 1.0, "x0", "sqrt needs x ≥ 0 over the range (got [-0.5, 1])");
  refused("reciprocal", -1.0, 1.0, "x0", "reciprocal needs a range without 0 (got [-1, 1])");
  refused("tan", 0.0, 2.0, "x1", "tan needs a range without an odd multiple of π/2 (got [0, 2])");
  refused("exp", 0.0, 1000.0, "x1", "exp needs finite values over the range (got [0, 1000])");
  for (const auto& [name, x0, x1] :
       {std::tuple{"log10", 1.0, 10.0}, std::tuple{"sqrt", 0.0, 4.0}, std::tuple{"reciprocal", -3.0, -1.0},
        std::tuple{"tan", 2.0, 4.0}, std::tuple{"exp", 0.0, 700.0}, std::tuple{"sin", -100.0, 100.0}}) {
    INFO(name);
    CHECK_FALSE(checkFunctionRange(*findNamedFunction(name), x0, x1).has_value());
  }
}
