#include "kinematics/synthesis/named_function.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <string>

namespace linkwright::kinematics {
namespace {

Error rangeError(const char* field, const NamedFunction& function, const std::string& needs, double x0, double x1) {
  return Error{
      ErrorCode::InvalidValue, field,
      std::string(function.name) + " needs " + needs + " (got [" + formatNumber(x0) + ", " + formatNumber(x1) + "])"};
}

}  // namespace

const std::vector<NamedFunction>& namedFunctions() {
  static const std::vector<NamedFunction> functions{
      {"log10", "log₁₀ x", [](double x) { return std::log10(x); }},
      {"ln", "ln x", [](double x) { return std::log(x); }},
      {"exp", "eˣ", [](double x) { return std::exp(x); }},
      {"sqrt", "√x", [](double x) { return std::sqrt(x); }},
      {"square", "x²", [](double x) { return x * x; }},
      {"cube", "x³", [](double x) { return x * x * x; }},
      {"reciprocal", "1/x", [](double x) { return 1.0 / x; }},
      {"sin", "sin x (x in rad)", [](double x) { return std::sin(x); }},
      {"cos", "cos x (x in rad)", [](double x) { return std::cos(x); }},
      {"tan", "tan x (x in rad)", [](double x) { return std::tan(x); }},
  };
  return functions;
}

const NamedFunction* findNamedFunction(std::string_view name) {
  for (const NamedFunction& f : namedFunctions())
    if (f.name == name) return &f;
  return nullptr;
}

std::optional<Error> checkFunctionRange(const NamedFunction& function, double x0, double x1) {
  const std::string_view name = function.name;
  if ((name == "log10" || name == "ln") && !(x0 > 0.0))
    return rangeError("x0", function, "x > 0 over the range", x0, x1);
  if (name == "sqrt" && x0 < 0.0) return rangeError("x0", function, "x ≥ 0 over the range", x0, x1);
  if (name == "reciprocal" && x0 <= 0.0 && x1 >= 0.0) return rangeError("x0", function, "a range without 0", x0, x1);
  // tan's poles are at odd multiples of π/2: both ends must lie between the same two.
  if (name == "tan" && std::floor(x0 / kPi - 0.5) != std::floor(x1 / kPi - 0.5))
    return rangeError("x1", function, "a range without an odd multiple of π/2", x0, x1);
  if (!std::isfinite(function.f(x0)) || !std::isfinite(function.f(x1)))
    return rangeError(std::isfinite(function.f(x0)) ? "x1" : "x0", function, "finite values over the range", x0, x1);
  return std::nullopt;
}

}  // namespace linkwright::kinematics
