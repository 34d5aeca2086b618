#pragma once
// How the driver's coordinate q moves in time (for a crank, its angle in rad): a motion law
// gives q(t), q̇(t) and q̈(t) exactly, so a sweep on a time base solves the linkage at each
// instant with the driver's true rates, its α-terms included, instead of one constant ω and α.
//
//   constant velocity   q = q0 + v·t
//   ramp to speed       from rest at q0, constant acceleration a = v/T until t = T, then v:
//                       q = q0 + a·t²/2 (t ≤ T),  q0 + v·T/2 + v·(t − T) (t > T)
//   cycloidal rise      u = t/T in [0, 1]: q = q0 + h·(u − sin(2πu)/(2π)),
//                       q̇ = (h/T)(1 − cos 2πu), q̈ = (2πh/T²) sin 2πu (peak 2πh/T²)
//   3-4-5 polynomial    q = q0 + h·(10u³ − 15u⁴ + 6u⁵), q̇ = (h/T)(30u² − 60u³ + 30u⁴),
//                       q̈ = (h/T²)(60u − 180u² + 120u³)
//   table               q(t) through measured points, a C² cubic spline whose end slopes are
//                       those of the cubic through the four end points: a cubic polynomial
//                       is reproduced to round-off
// Before t = 0 a law holds q0 at rest, after a rise q0 + h; outside its rows a table holds
// its first or last point at rest (a sweep on a time base stays within them).
// Times in s; q in the driver's unit (rad for a crank), q̇ per s, q̈ per s².

#include "kinematics/model/driver.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <optional>
#include <variant>
#include <vector>

namespace linkwright::kinematics {

struct ConstantVelocity {
  double start = 0.0;     ///< q at t = 0
  double velocity = 0.0;  ///< q̇
  bool operator==(const ConstantVelocity&) const = default;
};

struct RampToSpeed {
  double start = 0.0;     ///< q at t = 0, at rest
  double velocity = 0.0;  ///< q̇ reached at t = rampTime and kept
  double rampTime = 1.0;  ///< s, > 0
  bool operator==(const RampToSpeed&) const = default;
};

struct CycloidalRise {
  double start = 0.0;
  double rise = 0.0;      ///< h: q goes from start to start + h
  double duration = 1.0;  ///< T, s, > 0
  bool operator==(const CycloidalRise&) const = default;
};

struct PolynomialRise {  ///< the 3-4-5 polynomial
  double start = 0.0;
  double rise = 0.0;
  double duration = 1.0;
  bool operator==(const PolynomialRise&) const = default;
};

/// q(t) through measured points (at least four, times strictly increasing). Build it with
/// makeTableLaw, which fits the spline once.
struct TableLaw {
  std::vector<double> time;       ///< s
  std::vector<double> position;   ///< q at each time
  std::vector<double> curvature;  ///< the spline's q̈ at each time (makeTableLaw's)
  bool operator==(const TableLaw&) const = default;
};

using MotionLaw = std::variant<ConstantVelocity, RampToSpeed, CycloidalRise, PolynomialRise, TableLaw>;

/// The law's state at time `t` (s). The law must be valid (checkMotionLaw).
DriverState motionAt(const MotionLaw& law, double t);

/// A table law through (time, position) points, or an Error naming the row: lists of different
/// lengths, fewer than four points, a non-finite value, or times not strictly increasing.
Result<TableLaw> makeTableLaw(std::vector<double> time, std::vector<double> position);

/// Error naming the first invalid field ("law.duration", "law.velocity", …) and the value;
/// positions, speeds and accelerations within the input domain of the driver's kind.
std::optional<Error> checkMotionLaw(const MotionLaw& law, InputKind kind = InputKind::Angle);

/// The times over which `law` is defined by data: the table's first and last time; nullopt
/// for the closed-form laws, which are defined at every time.
std::optional<std::pair<double, double>> lawTimeSpan(const MotionLaw& law);

}  // namespace linkwright::kinematics
