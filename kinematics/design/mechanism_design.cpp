#include "kinematics/design/mechanism_design.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>

namespace linkwright::kinematics {

std::optional<Error> checkDesign(const MechanismDesign& d) {
  if (auto e = checkMechanism(d.mechanism)) return e;
  if (auto e = checkDriveAndGrid(d.omega, d.alpha, d.fromDeg, d.toDeg, d.samples)) return e;
  return checkDesignDynamics(d.mechanism, d.dynamics);
}

std::optional<Error> checkDesign(const Design& d) {
  return std::visit([](const auto& x) { return checkDesign(x); }, d);
}

Result<Mechanism> buildMechanism(const Design& d) {
  if (const auto* f = std::get_if<FourBarDesign>(&d)) return buildMechanism(*f);
  const auto& m = std::get<MechanismDesign>(d);
  if (auto e = checkDesign(m)) return *e;
  return m.mechanism;
}

SweepSpec designSweepSpec(const MechanismDesign& d) {
  return {degToRad(d.fromDeg), degToRad(d.toDeg), d.samples, d.omega, d.alpha};
}

SweepSpec designSweepSpec(const Design& d) {
  return std::visit([](const auto& x) { return designSweepSpec(x); }, d);
}

const std::string& designLengthUnit(const Design& d) {
  if (const auto* f = std::get_if<FourBarDesign>(&d)) return f->lengthUnit;
  return std::get<MechanismDesign>(d).mechanism.lengthUnit;
}

MechanismDesign designFromExample(const MechanismExample& e) {
  MechanismDesign d;
  d.kind = e.kind;
  d.mechanism = e.mechanism;
  d.omega = e.omega;
  d.dynamics = e.dynamics;
  d.fromDeg = e.fromDeg;
  d.toDeg = e.toDeg;
  d.samples = samplesEveryHalfDegree(e.fromDeg, e.toDeg);
  return d;
}

std::optional<Design> designForExample(const std::string& name) {
  if (const auto f = findFourBarExample(name)) return Design{designFromExample(*f)};
  if (const auto m = findMechanismExample(name)) return Design{designFromExample(*m)};
  return std::nullopt;
}

}  // namespace linkwright::kinematics
