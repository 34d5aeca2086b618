#include "kinematics/analysis/instant_centres.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

namespace linkwright::kinematics {
namespace {

// ±d name the same point at infinity; one representative keeps output and comparisons stable.
Eigen::Vector2d canonicalDirection(const Eigen::Vector2d& d) {
  return d.x() > 0.0 || (d.x() == 0.0 && d.y() > 0.0) ? d : Eigen::Vector2d(-d);
}

InstantCentre finite(const Eigen::Vector2d& p) { return {CentreKind::Finite, p, Eigen::Vector2d::Zero()}; }
InstantCentre atInfinity(const Eigen::Vector2d& d) {
  return {CentreKind::AtInfinity, Eigen::Vector2d::Zero(), canonicalDirection(d.normalized())};
}

// A line through a point, with a unit direction.
struct Line {
  Eigen::Vector2d point;
  Eigen::Vector2d direction;
};

// The line through two centres, at most one of them at infinity (Kennedy's lines here always
// join two primary centres, which are distinct joints or the slider's direction).
Line lineThrough(const InstantCentre& a, const InstantCentre& b) {
  if (a.kind == CentreKind::AtInfinity) return {b.position, a.direction};
  if (b.kind == CentreKind::AtInfinity) return {a.position, b.direction};
  return {a.position, (b.position - a.position).normalized()};
}

InstantCentre intersect(const Line& l1, const Line& l2, double scale) {
  const double sine = cross(l1.direction, l2.direction);
  const Eigen::Vector2d offset = l2.point - l1.point;
  if (std::abs(sine) <= kCentreTolerance) {
    if (std::abs(cross(l1.direction, offset)) <= kCentreTolerance * scale)
      return {CentreKind::Indeterminate, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
    return atInfinity(l1.direction);
  }
  return finite(l1.point + (cross(offset, l2.direction) / sine) * l1.direction);
}

std::optional<Error> checkPoint(const Eigen::Vector2d& p, const std::string& name) {
  if (auto e = checkCoordinate(p.x(), name + ".x")) return e;
  return checkCoordinate(p.y(), name + ".y");
}

// Error if the two ends of a link coincide (the link has no direction there).
std::optional<Error> checkDistinct(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& what,
                                   double scale) {
  if ((b - a).norm() > kCentreTolerance * scale) return std::nullopt;
  return Error{ErrorCode::InvalidValue, what, what + " has coincident ends: its joints are at the same point"};
}

// Kennedy's two secondary centres from the four primary ones.
void addSecondaryCentres(InstantCentres& c) {
  c.i13 = intersect(lineThrough(c.i12, c.i23), lineThrough(c.i14, c.i34), c.scale);
  c.i24 = intersect(lineThrough(c.i12, c.i14), lineThrough(c.i23, c.i34), c.scale);
}

// A ratio p/q of signed distances, with |q| ≤ tolerance·scale an infinite ratio.
Ratio ratioOf(double p, double q, double scale) {
  if (std::abs(q) <= kCentreTolerance * scale) return {RatioKind::Infinite, 0.0};
  if (std::abs(p) <= kCentreTolerance * scale) return {RatioKind::Finite, 0.0};
  return {RatioKind::Finite, p / q};
}

Ratio inverse(const Ratio& r) {
  if (r.kind == RatioKind::Infinite) return {RatioKind::Finite, 0.0};
  if (r.kind == RatioKind::Finite && r.value == 0.0) return {RatioKind::Infinite, 0.0};
  if (r.kind == RatioKind::Finite) return {RatioKind::Finite, 1.0 / r.value};
  return r;
}

}  // namespace

Result<InstantCentres> fourBarInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& o4,
                                             const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  for (const auto& [p, name] : {std::pair{&o2, "O2"}, {&o4, "O4"}, {&b, "B"}, {&c, "C"}})
    if (auto e = checkPoint(*p, name)) return *e;
  InstantCentres out;
  out.linkage = CentreLinkage::FourBar;
  out.scale = std::max({(b - o2).norm(), (c - b).norm(), (c - o4).norm(), (o4 - o2).norm()});
  for (const auto& [p, q, what] :
       {std::tuple{&o2, &o4, "frame"}, {&o2, &b, "crank"}, {&b, &c, "coupler"}, {&o4, &c, "rocker"}})
    if (auto e = checkDistinct(*p, *q, what, out.scale)) return *e;
  out.i12 = finite(o2);
  out.i14 = finite(o4);
  out.i23 = finite(b);
  out.i34 = finite(c);
  addSecondaryCentres(out);
  return out;
}

Result<InstantCentres> sliderCrankInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& b,
                                                 const Eigen::Vector2d& c, const Eigen::Vector2d& guideDirection) {
  for (const auto& [p, name] : {std::pair{&o2, "O2"}, {&b, "B"}, {&c, "C"}, {&guideDirection, "guide direction"}})
    if (auto e = checkPoint(*p, name)) return *e;
  if (!(guideDirection.norm() > 0.0))
    return Error{ErrorCode::InvalidValue, "guide direction", "guide direction must not be zero"};
  InstantCentres out;
  out.linkage = CentreLinkage::SliderCrank;
  out.guideDirection = guideDirection.normalized();
  out.scale = std::max((b - o2).norm(), (c - b).norm());
  for (const auto& [p, q, what] : {std::tuple{&o2, &b, "crank"}, {&b, &c, "rod"}})
    if (auto e = checkDistinct(*p, *q, what, out.scale)) return *e;
  out.i12 = finite(o2);
  out.i14 = atInfinity(perp(out.guideDirection));  // the slider translates along the guide
  out.i23 = finite(b);
  out.i34 = finite(c);
  addSecondaryCentres(out);
  return out;
}

Result<InstantCentres> instantCentres(const Mechanism& m, const Pose& pose) {
  if (auto e = checkMechanism(m)) return *e;
  if (pose.position.size() != m.points.size())
    return Error{ErrorCode::InvalidStructure, "pose",
                 "the pose has " + std::to_string(pose.position.size()) + " points but the mechanism has " +
                     std::to_string(m.points.size())};
  // What the linkage is decides the centres; where its links carry points does not matter.
  const auto at = [&pose](PointId p) -> const Eigen::Vector2d& { return pose.position[p.index]; };
  if (const auto f = asFourBar(m, PointsOnLinks::AnyLink))
    return fourBarInstantCentres(at(f->o2), at(f->o4), at(f->b), at(f->c));
  if (const auto s = asSliderCrank(m, PointsOnLinks::AnyLink))
    return sliderCrankInstantCentres(at(s->o2), at(s->b), at(s->c),
                                     Eigen::Vector2d(std::cos(s->guideAngle), std::sin(s->guideAngle)));
  return Error{ErrorCode::InvalidStructure, "mechanism",
               "instant centres are computed for four-bars and slider-cranks only: this linkage is neither (a crank, "
               "one joint on its tip held by a second ground pivot or on a ground guide, and points fixed on their "
               "links)"};
}

MechanicalAdvantage mechanicalAdvantage(const InstantCentres& c) {
  MechanicalAdvantage out;
  if (c.i24.kind == CentreKind::Indeterminate) {
    out.velocityRatio = out.advantage = {RatioKind::Undefined, 0.0};
    return out;
  }
  if (c.linkage == CentreLinkage::FourBar) {
    if (c.i24.kind == CentreKind::AtInfinity) {
      out.velocityRatio = out.advantage = {RatioKind::Finite, 1.0};  // links 2 and 4 turn together
      return out;
    }
    const Eigen::Vector2d e = (c.i14.position - c.i12.position).normalized();
    out.velocityRatio =
        ratioOf((c.i24.position - c.i12.position).dot(e), (c.i24.position - c.i14.position).dot(e), c.scale);
  } else if (c.i24.kind == CentreKind::AtInfinity) {
    out.velocityRatio = {RatioKind::Infinite, 0.0};  // rod normal to the guide
  } else {
    const double s = (c.i24.position - c.i12.position).dot(perp(c.guideDirection));
    const bool deadCentre = std::abs(s) <= kCentreTolerance * c.scale;  // crank and rod in line
    out.velocityRatio = {RatioKind::Finite, deadCentre ? 0.0 : -s};
  }
  out.advantage = inverse(out.velocityRatio);
  return out;
}

}  // namespace linkwright::kinematics
