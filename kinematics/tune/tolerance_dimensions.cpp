#include "kinematics/tune/tolerance_dimensions.h"

#include "kinematics/model/recognise.h"

#include <cmath>
#include <variant>

namespace linkwright::kinematics {
namespace {

// "B–C length": the ends of the bar a length holds.
std::string bar(const Mechanism& m, PointId from, std::size_t to) {
  return m.points[from.index].name + "–" + m.points[to].name + " length";
}

std::string nameOf(const Mechanism& m, const Parameter& p) {
  using S = ParameterSlot;
  const std::size_t i = p.point.index;
  const std::string& point = m.points[i].name;
  const PointDefinition& d = m.points[i].definition;
  switch (p.slot) {
  case S::FrameLength: return "frame length";
  case S::CrankLength: return "crank length";
  case S::CouplerLength: return "coupler length";
  case S::RockerLength: return "rocker length";
  case S::FrameAngle: return point + " across the frame line";
  case S::X: return std::holds_alternative<PathPoint>(d) ? point + " path centre x" : point + " x";
  case S::Y: return std::holds_alternative<PathPoint>(d) ? point + " path centre y" : point + " y";
  case S::Length:
    if (const auto* c = std::get_if<CrankPoint>(&d)) return bar(m, c->pivot, i);
    if (const auto* r = std::get_if<RrrPoint>(&d)) return bar(m, r->first, i);
    if (const auto* s = std::get_if<RrpPoint>(&d)) return bar(m, s->first, i);
    if (const auto* a = std::get_if<ActuatorPoint>(&d)) return bar(m, a->first, i);
    if (const auto* s = std::get_if<RprPoint>(&d)) return bar(m, s->pivot, i);
    return point + " path radius";
  case S::SecondLength: return bar(m, std::get<RrrPoint>(d).second, i);
  case S::Along: return point + " along its link";
  case S::Across: return point + " across its link";
  case S::GuideX: return point + " guide x";
  case S::GuideY: return point + " guide y";
  case S::SecondGuideX: return point + " second guide x";
  case S::SecondGuideY: return point + " second guide y";
  case S::ConstraintLength: {
    const DistanceConstraint& c = m.constraints[p.constraint];
    return bar(m, c.first, c.second.index);
  }
  case S::PathX: return point + " path vertex " + std::to_string(p.vertex + 1) + " x";
  case S::PathY: return point + " path vertex " + std::to_string(p.vertex + 1) + " y";
  default: return point;
  }
}

bool toleranced(const Mechanism& m, const Parameter& p) {
  if (p.slot == ParameterSlot::FrameAngle) return true;
  if (parameterUnit(p.slot) == ParameterUnit::Angle) return false;
  // A free point's x and y are Newton's start, not a dimension.
  return !(std::holds_alternative<FreePoint>(m.points[p.point.index].definition) &&
           (p.slot == ParameterSlot::X || p.slot == ParameterSlot::Y));
}

// O4 moved by `offset` at right angles to the frame line of `nominal`, CCW.
void moveAcrossFrame(Mechanism& m, const Mechanism& nominal, double offset) {
  const auto fourBar = asFourBar(nominal);
  if (!fourBar) return;
  const double a = fourBar->frameAngle;
  std::get<GroundPoint>(m.points[fourBar->o4.index].definition).position +=
      offset * Eigen::Vector2d(-std::sin(a), std::cos(a));
}

}  // namespace

std::vector<ToleranceDimension> toleranceDimensions(const Mechanism& m) {
  std::vector<ToleranceDimension> out;
  for (const Parameter& p : parametersOf(m)) {
    if (!toleranced(m, p)) continue;
    const bool across = p.slot == ParameterSlot::FrameAngle;
    out.push_back({p, nameOf(m, p), across ? 0.0 : parameterValue(m, p).value_or(0.0)});
  }
  return out;
}

Mechanism offsetDimensions(const Mechanism& mechanism, const std::vector<ToleranceDimension>& dimensions,
                           const std::vector<double>& offsets) {
  Mechanism m = mechanism;
  for (const bool named : {true, false}) {
    for (std::size_t d = 0; d < dimensions.size(); ++d) {
      const Parameter& p = dimensions[d].parameter;
      if (isFourBarDimension(p.slot) != named || offsets[d] == 0.0) continue;
      if (p.slot == ParameterSlot::FrameAngle) moveAcrossFrame(m, mechanism, offsets[d]);
      else setParameter(m, p, parameterValue(mechanism, p).value_or(0.0) + offsets[d]);
    }
  }
  return m;
}

Mechanism steppedMechanism(const Mechanism& mechanism, const ToleranceDimension& dimension) {
  return offsetDimensions(mechanism, {dimension}, {1.0});
}

}  // namespace linkwright::kinematics
