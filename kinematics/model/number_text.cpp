#include "kinematics/model/number_text.h"

#include <array>
#include <charconv>
#include <cmath>

namespace linkwright::kinematics {

namespace {
const std::string kUndefined = "undefined";
}

std::string formatDouble(double value) {
  if (!std::isfinite(value)) return "";
  if (value == 0.0) return "0";  // also folds -0 into 0
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  if (ec != std::errc{}) return "";  // cannot happen: 32 characters hold any shortest double
  return std::string(buffer.data(), end);
}

std::string formatJsonNumber(double value) { return std::isfinite(value) ? formatDouble(value) : "null"; }

std::string formatShort(double value, int significant) {
  if (!std::isfinite(value)) return kUndefined;
  if (value == 0.0) return "0";
  std::array<char, 64> buffer{};
  const auto [end, ec] =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::general, significant);
  if (ec != std::errc{}) return kUndefined;
  return std::string(buffer.data(), end);
}

std::string formatFixed(double value, int decimals) {
  if (!std::isfinite(value)) return kUndefined;
  // Room for every double in fixed notation: 309 integer digits, a sign, a point, decimals.
  std::array<char, 400> buffer{};
  const auto [end, ec] =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed, decimals);
  if (ec != std::errc{}) return kUndefined;  // more than 89 decimals
  std::string text(buffer.data(), end);
  // "-0.00" reads as a sign that is not there: print it as "0.00".
  if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) text.erase(0, 1);
  return text;
}

}  // namespace linkwright::kinematics
