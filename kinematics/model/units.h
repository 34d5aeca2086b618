#pragma once
// Unit conversions used at the edges (CLI, CSV, examples). The core works in radians and
// seconds; lengths are in whatever unit the mechanism names (see Mechanism::lengthUnit).

#include <numbers>

namespace linkwright::kinematics {

inline constexpr double kPi = std::numbers::pi;

/// Degrees to radians.
constexpr double degToRad(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double radToDeg(double radians) { return radians * (180.0 / kPi); }
/// Revolutions per minute to rad/s.
constexpr double rpmToRadPerSec(double rpm) { return rpm * (2.0 * kPi / 60.0); }
/// rad/s to revolutions per minute.
constexpr double radPerSecToRpm(double omega) { return omega * (60.0 / (2.0 * kPi)); }

} // namespace linkwright::kinematics
