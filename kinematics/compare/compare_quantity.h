#pragma once
// What a column of another tool's table can be compared with, and in which units. The
// quantities are the columns `analyze` writes (kinematics/solve/sweep_columns.h), named without
// their unit suffix: "coupler_angle", "rocker_omega", "rocker_alpha", "transmission_angle",
// "C_x", "C_vx", "C_ax", the input "crank_angle". A slider's position, velocity and
// acceleration are its point's x/y, vx/vy and ax/ay. Each quantity has a dimension, and each
// dimension the units another tool may write it in, with the factor to the unit the sweep
// columns use (degrees for angles, rad/s, rad/s², the linkage's length unit).

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep_columns.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics::compare {

/// What a quantity measures; it decides the units a column of it may be in.
enum class Dimension { Angle, AngularRate, AngularAcceleration, Length, Velocity, Acceleration, Time };

/// A quantity a table column can be mapped to: `key` is the sweep column's name without its
/// unit ("rocker_omega" for "rocker_omega_rad_s").
struct CompareQuantity {
  std::string key;
  kinematics::SweepColumn column;
  Dimension dimension = Dimension::Angle;
};

/// A unit a column may be written in: value in the sweep column's unit = file value × `factor`.
struct UnitChoice {
  std::string name;  ///< as typed: "deg", "rad/s", "rpm", "mm/s2"
  double factor = 1.0;
};

/// Every quantity of `mechanism` that can be compared (all of analyze's columns with rates,
/// except time), in analyze's order.
std::vector<CompareQuantity> compareQuantities(const Mechanism& mechanism);

/// The quantity named `key` (or a full sweep column name such as "rocker_omega_rad_s", whose
/// unit is then given in `impliedUnit`), or nullopt.
std::optional<CompareQuantity> findQuantity(const Mechanism& mechanism, const std::string& key,
                                            std::string* impliedUnit = nullptr);

/// The units accepted for `dimension`, the sweep's own first. Lengths: the linkage's unit,
/// and m, cm, mm, in, ft when the linkage's unit is one of them.
std::vector<UnitChoice> unitsFor(Dimension dimension, const std::string& lengthUnit);

/// The unit named `name` for `dimension` ("rad/s^2" and "rad/s²" read as "rad/s2"), or nullopt.
std::optional<UnitChoice> findUnit(Dimension dimension, const std::string& lengthUnit, const std::string& name);

/// The accepted unit names joined for a message: "deg, rad".
std::string unitList(Dimension dimension, const std::string& lengthUnit);

/// The largest magnitude a column of `dimension` may hold, in the sweep column's unit (degrees
/// for angles, seconds for times): what model/validate.h lets a linkage reach, with a lever ratio
/// of up to its kMaxLengthRatio: ±1e6° (kMaxAngleDeg), 1e12 rad/s, 1e24 rad/s², 1e9 in the length
/// unit (kMaxLength) and 1e15, 1e21 per s and s²; 1e9 s. A value beyond it is a wrong mapping or
/// unit, not a measurement.
double largestMagnitude(Dimension dimension);

/// "angle", "angular velocity", …: for messages.
const char* dimensionName(Dimension dimension);

}  // namespace linkwright::kinematics::compare
