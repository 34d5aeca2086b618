#pragma once
// Unit conversions used at the edges (CLI, CSV, examples). The core works in radians and
// seconds; lengths are in whatever unit the mechanism names (see Mechanism::lengthUnit).

namespace linkwright::kinematics {

// Spelled out rather than std::numbers::pi: Qt 6.4's moc cannot parse <numbers>.
inline constexpr double kPi = 3.141592653589793238462643383279502884;

/// Degrees to radians.
constexpr double degToRad(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double radToDeg(double radians) { return radians * (180.0 / kPi); }
/// Revolutions per minute to rad/s.
constexpr double rpmToRadPerSec(double rpm) { return rpm * (2.0 * kPi / 60.0); }
/// rad/s to revolutions per minute.
constexpr double radPerSecToRpm(double omega) { return omega * (60.0 / (2.0 * kPi)); }

} // namespace linkwright::kinematics
