#pragma once
// Locale-independent, round-trip number formatting for CSV, JSON and messages
// (std::to_chars: the shortest text that reads back to the same double). The last guard of
// "Linkwright never prints nan or inf": none of these writes either. A value that is still
// not finite, whatever let it through the input domain, becomes an empty CSV cell, a JSON
// null, or "undefined" in text meant for people.

#include <string>

namespace linkwright::kinematics {

/// Shortest round-trip decimal text of `value`, '.' as decimal point whatever the locale.
/// Negative zero prints as "0"; NaN and infinities print as "" (an empty CSV cell).
std::string formatDouble(double value);

/// formatDouble for a JSON number: NaN and infinities print as "null".
std::string formatJsonNumber(double value);

/// At most `significant` significant digits, trailing zeros dropped (for messages: "115",
/// "0.333333", "1e-06"); "undefined" for NaN and infinities.
std::string formatShort(double value, int significant = 6);

/// Fixed-point text with `decimals` digits after the point (for human-readable tables);
/// "undefined" for NaN and infinities.
std::string formatFixed(double value, int decimals);

}  // namespace linkwright::kinematics
