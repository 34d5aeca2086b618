#pragma once
// Unit conversions used at the edges (CLI, CSV, examples). The core works in radians and
// seconds; lengths are in whatever unit the mechanism names (see Mechanism::lengthUnit).

#include <cmath>
#include <optional>
#include <string>

namespace linkwright::kinematics {

// Spelled out rather than std::numbers::pi: Qt 6.4's moc cannot parse <numbers>.
inline constexpr double kPi = 3.141592653589793238462643383279502884;

/// The angle (rad) brought into (−π, π]. Angles a step or two out of range (the usual case:
/// a sum of two wrapped angles, a difference between samples) take a branch, not a division.
inline double wrapAngle(double angle) {
  if (angle > -kPi && angle <= kPi) return angle;
  if (angle > kPi && angle <= 3.0 * kPi) return angle - 2.0 * kPi;
  if (angle > -3.0 * kPi && angle <= -kPi) return angle + 2.0 * kPi;
  const double r = std::remainder(angle, 2.0 * kPi);
  return r <= -kPi ? r + 2.0 * kPi : r;
}

/// Degrees to radians.
constexpr double degToRad(double degrees) { return degrees * (kPi / 180.0); }
/// Radians to degrees.
constexpr double radToDeg(double radians) { return radians * (180.0 / kPi); }
/// Revolutions per minute to rad/s.
constexpr double rpmToRadPerSec(double rpm) { return rpm * (2.0 * kPi / 60.0); }
/// rad/s to revolutions per minute.
constexpr double radPerSecToRpm(double omega) { return omega * (60.0 / (2.0 * kPi)); }

/// How many metres one `unit` is, for "m", "cm", "mm", "in" (25.4 mm) and "ft" (304.8 mm);
/// nullopt for any other name. Kinematics accept any unit label; forces need this one.
inline std::optional<double> metresPerLengthUnit(const std::string& unit) {
  if (unit == "m") return 1.0;
  if (unit == "cm") return 0.01;
  if (unit == "mm") return 0.001;
  if (unit == "in") return 0.0254;
  if (unit == "ft") return 0.3048;
  return std::nullopt;
}

}  // namespace linkwright::kinematics
