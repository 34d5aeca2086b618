#include "kinematics/model/validate.h"

#include "kinematics/model/number_text.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

// Bounds are powers of ten: "1e6" reads better than to_chars' "1e+06".
std::string boundText(double bound) {
  const double exponent = std::round(std::log10(bound));
  if (std::pow(10.0, exponent) == bound) return "1e" + std::to_string(static_cast<int>(exponent));
  return formatShort(bound, 6);
}

Error valueError(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

}  // namespace

std::optional<Error> checkCoordinate(double value, const std::string& field) {
  if (!std::isfinite(value)) return valueError(field, field + " must be finite (got " + formatNumber(value) + ")");
  if (std::abs(value) > kMaxLength)
    return valueError(field,
                      field + " must be within ±" + boundText(kMaxLength) + " (got " + formatNumber(value) + ")");
  return std::nullopt;
}

std::optional<Error> checkLength(double value, const std::string& field, const std::string& what) {
  if (!(std::isfinite(value) && value > 0.0))
    return valueError(field, field + " " + what + " must be positive and finite (got " + formatNumber(value) + ")");
  if (value < kMinLength || value > kMaxLength)
    return valueError(field, field + " " + what + " must be between " + boundText(kMinLength) + " and " +
                                 boundText(kMaxLength) + " (got " + formatNumber(value) + ")");
  return std::nullopt;
}

std::optional<Error> checkMagnitude(double value, const std::string& field, double max, const std::string& unit) {
  if (std::isfinite(value) && std::abs(value) <= max) return std::nullopt;
  return valueError(field, field + " must be finite and within ±" + boundText(max) + " " + unit + " (got " +
                               formatNumber(value) + ")");
}

std::optional<Error> checkComputedMagnitude(double value, const std::string& field, double max,
                                            const std::string& unit) {
  if (std::isfinite(value) && std::abs(value) <= max) return std::nullopt;
  const std::string bound = "±" + boundText(max) + " " + unit;
  if (!std::isfinite(value)) return valueError(field, field + " overflows for these inputs (beyond " + bound + ")");
  return valueError(field, field + " would be " + formatNumber(value) + ", beyond " + bound);
}

std::optional<Error> checkNonNegative(double value, const std::string& field, double max, const std::string& unit) {
  if (std::isfinite(value) && value >= 0.0 && value <= max) return std::nullopt;
  return valueError(
      field, field + " must be between 0 and " + boundText(max) + " " + unit + " (got " + formatNumber(value) + ")");
}

std::optional<Error> checkScale(double shortest, const std::string& shortestName, double largest,
                                const std::string& largestName, const std::string& unit) {
  if (largest <= kMaxLengthRatio * shortest) return std::nullopt;
  return valueError("lengths", "lengths span too wide a range: " + shortestName + " is " + formatNumber(shortest) +
                                   " " + unit + " but " + largestName + " is " + formatNumber(largest) + " " + unit +
                                   ", " + formatShort(largest / shortest, 3) + " times as much; a linkage's largest " +
                                   "dimension may be at most " + boundText(kMaxLengthRatio) +
                                   " times its shortest link");
}

}  // namespace linkwright::kinematics
