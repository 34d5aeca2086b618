#include "kinematics/design/design.h"

#include "kinematics/dynamics/crank_terms.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/work_count.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

std::optional<Error> checkDesign(const Design& d) {
  countDesignCheck();
  // A four-bar's lengths are named as its editors and the CLI name them ("lengths.coupler").
  if (const auto fourBar = asFourBar(d.mechanism, PointsOnLinks::AnyLink))
    if (auto e = checkFourBarLengths(fourBar->lengths)) {
      e->field = "lengths." + e->field;
      return e;
    }
  if (auto e = checkMechanism(d.mechanism)) return e;
  const InputKind kind = inputKind(d.mechanism);
  if (auto e = checkDriveAndGrid(d.omega, d.alpha, d.fromDeg, d.toDeg, d.samples, kind)) return e;
  if (d.time)
    if (auto e = checkTimeBase(*d.time, kind)) return e;
  return checkDesignDynamics(d.mechanism, d.dynamics);
}

std::optional<Error> checkDesignDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics) {
  auto e = checkDynamics(mechanism, dynamics);
  if (!e) return e;
  e->field = "dynamics." + e->field;
  e->message = "dynamics." + e->message;
  return e;
}

std::optional<Error> checkDriveAndGrid(double omega, double alpha, double fromDeg, double toDeg, std::size_t samples,
                                       InputKind kind) {
  const InputDomain d = inputDomain(kind);
  const bool angle = kind == InputKind::Angle;
  if (auto e = checkMagnitude(omega, "omega", d.rate, d.rateUnit)) return e;
  if (auto e = checkMagnitude(alpha, "alpha", d.acceleration, d.accelerationUnit)) return e;
  if (auto e =
          checkMagnitude(fromDeg, "fromDeg", angle ? kMaxAngleDeg : d.position, angle ? "degrees" : d.positionUnit))
    return e;
  if (auto e = checkMagnitude(toDeg, "toDeg", angle ? kMaxAngleDeg : d.position, angle ? "degrees" : d.positionUnit))
    return e;
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

SweepSpec designTurn(const Design& d) {
  const double from = degToRad(d.fromDeg);
  const std::size_t samples = std::clamp<std::size_t>(d.samples, 361, kMaxTurnSamples);
  return {from, from + 2.0 * kPi, samples, d.omega == 0.0 ? 1.0 : d.omega, 0.0};
}

SweepSpec designSweepSpec(const Design& d) {
  return {inputFromDisplay(d.mechanism, d.fromDeg),
          inputFromDisplay(d.mechanism, d.toDeg),
          d.samples,
          d.omega,
          d.alpha,
          d.time};
}

Result<Design> fourBarDesign(const FourBarLengths& lengths, Branch branch, const std::string& lengthUnit,
                             std::optional<CouplerPointSpec> couplerPoint) {
  auto mechanism = makeFourBar(lengths, branch, lengthUnit, couplerPoint);
  if (!mechanism) return mechanism.error();
  Design d;
  d.kind = "four-bar";
  d.mechanism = std::move(*mechanism);
  return d;
}

Design designFromExample(const Example& e) {
  Design d;
  d.kind = e.kind;
  d.mechanism = e.mechanism;
  d.omega = e.omega;
  d.alpha = e.alpha;
  d.dynamics = e.dynamics;
  d.fromDeg = e.fromDeg;
  d.toDeg = e.toDeg;
  d.samples = samplesEveryHalfDegree(e.fromDeg, e.toDeg);
  if (e.time) {
    d.time = e.time;
    d.samples = e.timeSamples;
  }
  return d;
}

std::optional<Design> designForExample(const std::string& name) {
  if (const auto e = findExample(name)) return designFromExample(*e);
  return std::nullopt;
}

}  // namespace linkwright::kinematics
