#include "kinematics/model/validate.h"

#include "kinematics/io/number_format.h"

#include <cmath>

namespace linkwright::kinematics {

std::string formatNumber(double value) { return io::formatDouble(value); }

std::optional<Error> checkFinite(double value, const std::string& field) {
  if (std::isfinite(value)) return std::nullopt;
  return Error{ErrorCode::InvalidValue, field,
               field + " must be finite (got " + formatNumber(value) + ")"};
}

std::optional<Error> checkPositive(double value, const std::string& field,
                                   const std::string& what) {
  if (std::isfinite(value) && value > 0.0) return std::nullopt;
  return Error{ErrorCode::InvalidValue, field,
               field + " " + what + " must be positive and finite (got " + formatNumber(value) +
                   ")"};
}

} // namespace linkwright::kinematics
