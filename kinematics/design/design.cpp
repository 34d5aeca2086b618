#include "kinematics/design/design.h"

#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::kinematics {

std::optional<Error> checkDesign(const FourBarDesign& d) {
  if (auto e = checkFourBarLengths(d.lengths)) {
    e->field = "lengths." + e->field;
    return e;
  }
  if (d.couplerPoint) {
    if (auto e = checkCoordinate(d.couplerPoint->along, "couplerPoint.along")) return e;
    if (auto e = checkCoordinate(d.couplerPoint->across, "couplerPoint.across")) return e;
  }
  // The lengths' spread (checkLinkageScale) is checked where the linkage is built.
  const auto mechanism = makeFourBar(d.lengths, d.branch, d.lengthUnit, d.couplerPoint);
  if (!mechanism) return mechanism.error();
  if (auto e = checkDriveAndGrid(d.omega, d.alpha, d.fromDeg, d.toDeg, d.samples)) return e;
  if (d.dynamics.empty()) return std::nullopt;
  return checkDesignDynamics(*mechanism, d.dynamics);
}

std::optional<Error> checkDesignDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics) {
  auto e = checkDynamics(mechanism, dynamics);
  if (!e) return e;
  e->field = "dynamics." + e->field;
  e->message = "dynamics." + e->message;
  return e;
}

std::optional<Error> checkDriveAndGrid(double omega, double alpha, double fromDeg, double toDeg, std::size_t samples) {
  if (auto e = checkMagnitude(omega, "omega", kMaxOmega, "rad/s")) return e;
  if (auto e = checkMagnitude(alpha, "alpha", kMaxAlpha, "rad/s²")) return e;
  if (auto e = checkMagnitude(fromDeg, "fromDeg", kMaxAngleDeg, "degrees")) return e;
  if (auto e = checkMagnitude(toDeg, "toDeg", kMaxAngleDeg, "degrees")) return e;
  if (toDeg <= fromDeg)
    return Error{
        ErrorCode::InvalidValue, "toDeg",
        "toDeg must be greater than fromDeg (got " + formatNumber(fromDeg) + " to " + formatNumber(toDeg) + ")"};
  if (samples < 2 || samples > static_cast<std::size_t>(kMaxSamples))
    return Error{
        ErrorCode::InvalidValue, "samples",
        "samples must be between 2 and " + std::to_string(kMaxSamples) + " (got " + std::to_string(samples) + ")"};
  return std::nullopt;
}

std::size_t samplesEveryHalfDegree(double fromDeg, double toDeg) {
  return static_cast<std::size_t>(std::lround((toDeg - fromDeg) / 0.5)) + 1;
}

Result<Mechanism> buildMechanism(const FourBarDesign& d) {
  if (auto e = checkDesign(d)) return *e;
  return makeFourBar(d.lengths, d.branch, d.lengthUnit, d.couplerPoint);
}

SweepSpec designSweepSpec(const FourBarDesign& d) {
  return {degToRad(d.fromDeg), degToRad(d.toDeg), d.samples, d.omega, d.alpha};
}

FourBarDesign designFromExample(const FourBarExample& e) {
  FourBarDesign d;
  d.lengths = e.lengths;
  d.lengthUnit = e.lengthUnit;
  d.branch = e.branch;
  d.omega = e.omega;
  d.alpha = e.alpha;
  d.couplerPoint = e.couplerPoint;
  d.dynamics = e.dynamics;
  d.fromDeg = e.fromDeg;
  d.toDeg = e.toDeg;
  d.samples = samplesEveryHalfDegree(e.fromDeg, e.toDeg);
  return d;
}

}  // namespace linkwright::kinematics
