#pragma once
// Boundary checks shared by every factory and parser: a number must be finite, and a
// length must be positive. Each returns an Error that names the field and the value.

#include "kinematics/model/result.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

/// Formats a double for messages with round-trip precision ("70", "-0.5", "nan", "inf").
std::string formatNumber(double value);

/// Error if `value` is NaN or infinite.
std::optional<Error> checkFinite(double value, const std::string& field);
/// Error if `value` is not strictly positive and finite (lengths, step sizes).
std::optional<Error> checkPositive(double value, const std::string& field,
                                   const std::string& what = "length");

} // namespace linkwright::kinematics
