#pragma once
// The functions a function generator can be asked to follow, by name (log10, ln, exp, sqrt,
// square, cube, reciprocal, sin, cos, tan), and the x ranges on which each is defined and
// finite. The CLI's --function and the designer's function list read this one table, and a
// range where the function is undefined is refused here, naming the field, so the synthesis
// never sees a NaN.

#include "kinematics/model/result.h"

#include <optional>
#include <string_view>
#include <vector>

namespace linkwright::kinematics {

struct NamedFunction {
  std::string_view name;   ///< as typed: "log10", "square", "reciprocal", …
  std::string_view label;  ///< as shown: "log₁₀ x", "x²", "1/x", …
  double (*f)(double);     ///< y = f(x); sin, cos and tan take x in radians
};

/// Every function, in the order a list shows them.
const std::vector<NamedFunction>& namedFunctions();

/// The function called `name`, or null.
const NamedFunction* findNamedFunction(std::string_view name);

/// Error naming "x0" or "x1" (the message starts with the name and the range) unless
/// `function` is defined and finite on all of [x0, x1] (x0 < x1, both finite).
std::optional<Error> checkFunctionRange(const NamedFunction& function, double x0, double x1);

}  // namespace linkwright::kinematics
