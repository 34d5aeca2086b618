#include "kinematics/model/driver.h"

#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

namespace linkwright::kinematics {

InputDomain inputDomain(InputKind kind) {
  if (kind == InputKind::Angle)
    return {degToRad(kMaxAngleDeg), kMaxOmega, kMaxAlpha, "rad (1e6 degrees)", "rad/s", "rad/s²", "omega", "alpha"};
  return {kMaxLength,       kMaxLength * kMaxOmega, kMaxLength * kMaxAlpha, "length units",
          "length units/s", "length units/s²",      "input velocity",       "input acceleration"};
}

bool isDriver(const PointDefinition& d) {
  return std::holds_alternative<CrankPoint>(d) || std::holds_alternative<PathPoint>(d) ||
         std::holds_alternative<ActuatorPoint>(d);
}

std::optional<PointId> driverPoint(const Mechanism& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (isDriver(m.points[i].definition)) return PointId{i};
  return std::nullopt;
}

InputKind inputKind(const Mechanism& m) {
  const auto driver = driverPoint(m);
  return driver && std::holds_alternative<CrankPoint>(m.points[driver->index].definition) ? InputKind::Angle
                                                                                          : InputKind::Length;
}

double inputPeriod(const Mechanism& m) { return inputKind(m) == InputKind::Angle ? 2.0 * kPi : 0.0; }

std::string inputName(const Mechanism& m) {
  const auto driver = driverPoint(m);
  if (!driver) return "input";
  const Point& p = m.points[driver->index];
  if (const auto* c = std::get_if<CrankPoint>(&p.definition)) {
    // A linkage driven from its rocker (design/redrive.h) names that link, not "crank".
    for (const Link& link : m.links)
      if ((link.first == c->pivot && link.second == *driver) || (link.first == *driver && link.second == c->pivot))
        return link.name + " angle";
    return "crank angle";
  }
  if (const auto* a = std::get_if<ActuatorPoint>(&p.definition))
    return "actuator " + m.points[a->base.index].name + "–" + p.name + " length";
  return p.name + " path position";
}

std::string inputUnit(const Mechanism& m) { return inputKind(m) == InputKind::Angle ? "°" : m.lengthUnit; }

double inputDisplayValue(const Mechanism& m, double q) { return inputKind(m) == InputKind::Angle ? radToDeg(q) : q; }

double inputFromDisplay(const Mechanism& m, double value) {
  return inputKind(m) == InputKind::Angle ? degToRad(value) : value;
}

}  // namespace linkwright::kinematics
