#include "kinematics/model/validate.h"

#include <array>
#include <charconv>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// A finite `value` as text: the shortest that reads back to it (as kinematics::formatDouble writes
// it), or to `significant` digits. The model formats its own messages, so that it depends on
// nothing above it.
std::string shortestText(double value, int significant = 0) {
  std::array<char, 64> buffer{};
  char* const first = buffer.data();
  char* const last = first + buffer.size();
  const auto [end, ec] = significant > 0 ? std::to_chars(first, last, value, std::chars_format::general, significant)
                                         : std::to_chars(first, last, value);
  return ec == std::errc{} ? std::string(first, end) : std::string();
}

// Bounds are powers of ten: "1e6" reads better than to_chars' "1e+06".
std::string boundText(double bound) {
  const double exponent = std::round(std::log10(bound));
  if (std::pow(10.0, exponent) == bound) return "1e" + std::to_string(static_cast<int>(exponent));
  return shortestText(bound, 6);
}

Error valueError(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

}  // namespace

std::string formatNumber(double value) {
  // The value the user gave, as they gave it: a message may quote "nan" or "inf" back.
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value == 0.0 ? "0" : shortestText(value);
}

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
                                   ", " + shortestText(largest / shortest, 3) + " times as much; a linkage's largest " +
                                   "dimension may be at most " + boundText(kMaxLengthRatio) +
                                   " times its shortest link");
}

}  // namespace linkwright::kinematics
