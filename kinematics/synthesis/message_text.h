#pragma once
// Angles in the synthesis messages a user reads ("minimum transmission angle 31.2° is below
// 40°"): degrees, six significant digits, through the core's one number text.

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <string>

namespace linkwright::kinematics::synthesis_text {

/// An angle given in radians, written in degrees with its sign: "31.2°".
inline std::string degrees(double radians) { return formatShort(radToDeg(radians)) + "°"; }

}  // namespace linkwright::kinematics::synthesis_text
