#pragma once
// Numbers as text, the one place the core turns a double into characters: for CSV, JSON and
// messages alike. Locale-independent (std::to_chars), and round-trip where no precision is
// asked for: the shortest text that reads back to the same double.
//
// One rule for a value that is not finite, whatever let it through: it is never written as
// digits, "nan" or "inf". Where it would be, the medium's own word for "no value" stands: an
// empty CSV cell, a JSON null, "undefined" in text meant for people (messages, tables).

#include <string>

namespace linkwright::kinematics {

/// What text for people says in place of a value that is not finite.
inline constexpr const char* kUndefinedText = "undefined";

/// Shortest round-trip decimal text of `value`, '.' as decimal point whatever the locale.
/// Negative zero prints as "0"; NaN and infinities print as "" (an empty CSV cell).
std::string formatDouble(double value);

/// formatDouble for a JSON number: NaN and infinities print as "null".
std::string formatJsonNumber(double value);

/// formatDouble for people: a value a message quotes back at full precision ("70", "-0.5",
/// "1e+160"); "undefined" for NaN and infinities.
std::string formatNumber(double value);

/// At most `significant` significant digits, trailing zeros dropped (for messages: "115",
/// "0.333333", "1e-06"); "undefined" for NaN and infinities.
std::string formatShort(double value, int significant = 6);

/// formatShort with the exponent as people write it: "1e-9", "2.5e6", not "1e-09", "2.5e+06".
std::string formatCompact(double value, int significant = 6);

/// Fixed-point text with `decimals` digits after the point (for human-readable tables);
/// "undefined" for NaN and infinities.
std::string formatFixed(double value, int decimals);

}  // namespace linkwright::kinematics
