#include "kinematics/model/number_text.h"

#include <array>
#include <charconv>
#include <cmath>
#include <optional>

namespace linkwright::kinematics {
namespace {

enum class Style { Shortest, Significant, Fixed };

// The one conversion: the text of a finite `value`, or nothing for a value that is not finite
// (each public routine then writes its medium's word for it). Zero of either sign is "0" in the
// shortest and significant styles; a fixed "-0.00" reads as a sign that is not there, so it
// prints as "0.00".
std::optional<std::string> finiteText(double value, Style style, int precision = 0) {
  if (!std::isfinite(value)) return std::nullopt;
  if (value == 0.0 && style != Style::Fixed) return "0";
  // Room for every double in fixed notation: 309 integer digits, a sign, a point, decimals.
  std::array<char, 400> buffer{};
  char* const first = buffer.data();
  char* const last = first + buffer.size();
  const auto [end, ec] = style == Style::Shortest ? std::to_chars(first, last, value)
                         : style == Style::Significant
                             ? std::to_chars(first, last, value, std::chars_format::general, precision)
                             : std::to_chars(first, last, value, std::chars_format::fixed, precision);
  if (ec != std::errc{}) return std::nullopt;  // only past 89 fixed decimals
  std::string text(first, end);
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

}  // namespace

std::string formatDouble(double value) { return finiteText(value, Style::Shortest).value_or(""); }

std::string formatJsonNumber(double value) { return finiteText(value, Style::Shortest).value_or("null"); }

std::string formatNumber(double value) { return finiteText(value, Style::Shortest).value_or(kUndefinedText); }

std::string formatShort(double value, int significant) {
  return finiteText(value, Style::Significant, significant).value_or(kUndefinedText);
}

std::string formatCompact(double value, int significant) {
  std::string s = formatShort(value, significant);
  const std::size_t e = s.find('e');
  if (e == std::string::npos) return s;
  std::size_t digits = e + 1;
  if (s[digits] == '+') s.erase(digits, 1);
  else if (s[digits] == '-') ++digits;
  while (digits + 1 < s.size() && s[digits] == '0') s.erase(digits, 1);
  return s;
}

std::string formatFixed(double value, int decimals) {
  return finiteText(value, Style::Fixed, decimals).value_or(kUndefinedText);
}

}  // namespace linkwright::kinematics
