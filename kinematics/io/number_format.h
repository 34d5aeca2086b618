#pragma once
// Locale-independent, round-trip number formatting for CSV, JSON and messages
// (std::to_chars: the shortest text that reads back to the same double).

#include <string>

namespace linkwright::kinematics::io {

/// Shortest round-trip decimal text of `value`, '.' as decimal point whatever the locale.
/// Negative zero prints as "0"; NaN and infinities print as "nan", "inf", "-inf".
std::string formatDouble(double value);

/// At most `significant` significant digits, trailing zeros dropped (for messages: "115",
/// "0.333333", "1e-06").
std::string formatShort(double value, int significant = 6);

/// Fixed-point text with `decimals` digits after the point (for human-readable tables).
std::string formatFixed(double value, int decimals);

} // namespace linkwright::kinematics::io
