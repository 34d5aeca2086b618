#pragma once
// The driver: the one point whose definition takes the input coordinate q. A crank's q is its
// angle (rad); a point on a path's is its path coordinate s and a linear actuator's its length
// pin to pin (both in the mechanism's length unit). Every table, plot and message names the
// input from here, so an angle is never printed as a length or the reverse.

#include "kinematics/model/mechanism.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

enum class InputKind { Angle, Length };

/// The input domain (validate.h) for a driver's coordinate, rate and acceleration, with the
/// words messages use: a crank's angle within ±1e6 degrees, ω and α within the domain's; a
/// linear driver's position within ±kMaxLength, its speed within kMaxOmega·kMaxLength and its
/// acceleration within kMaxAlpha·kMaxLength (a point on a link of the largest size turning at
/// the largest ω and α moves that fast).
struct InputDomain {
  double position;
  double rate;
  double acceleration;
  const char* positionUnit;
  const char* rateUnit;
  const char* accelerationUnit;
  const char* rateName;          ///< "omega" or "input velocity"
  const char* accelerationName;  ///< "alpha" or "input acceleration"
};
InputDomain inputDomain(InputKind kind);

/// True for the definitions that take the input (CrankPoint, PathPoint, ActuatorPoint).
bool isDriver(const PointDefinition& definition);

/// The driver point: the first point that takes the input (checkMechanism allows one).
std::optional<PointId> driverPoint(const Mechanism& mechanism);

/// Angle for a crank, Length for a path or actuator driver (and for a mechanism without one).
InputKind inputKind(const Mechanism& mechanism);

/// The input's period: 2π for a crank (a turn brings it back), 0 for a linear input.
double inputPeriod(const Mechanism& mechanism);

/// What the input is, for messages and titles: "crank angle" (a crank's link by its name:
/// "rocker angle" for a four-bar driven from its rocker), "C path position",
/// "actuator A–C length".
std::string inputName(const Mechanism& mechanism);

/// The input's unit for display: "°" for a crank, else the length unit.
std::string inputUnit(const Mechanism& mechanism);

/// The input in display units: degrees for a crank (q in rad), else q itself.
double inputDisplayValue(const Mechanism& mechanism, double q);

/// The inverse of inputDisplayValue.
double inputFromDisplay(const Mechanism& mechanism, double value);

}  // namespace linkwright::kinematics
