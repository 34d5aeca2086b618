#pragma once
// Numbers in the synthesis messages a user reads ("minimum transmission angle 31.2° is below
// 40°"): six significant digits, locale-independent (std::to_chars), degrees for angles.

#include "kinematics/model/units.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace linkwright::kinematics::synthesis_text {

/// `value` to six significant digits ("0.333333", "1e+12"); "nan" / "inf" as they are.
inline std::string number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  std::array<char, 48> buffer{};
  const auto [end, ec] =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::general, 6);
  return ec == std::errc{} ? std::string(buffer.data(), end) : std::string();
}

/// An angle given in radians, written in degrees with its sign: "31.2°".
inline std::string degrees(double radians) { return number(radToDeg(radians)) + "°"; }

}  // namespace linkwright::kinematics::synthesis_text
