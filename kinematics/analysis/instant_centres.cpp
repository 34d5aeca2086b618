#include "kinematics/analysis/instant_centres.h"

#include "kinematics/analysis/centre_model.h"
#include "kinematics/analysis/kennedy.h"
#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

namespace linkwright::kinematics {
namespace {

// A joint's position, solved (a pose's) or passed in: any finite point. The input domain bounds
// what is typed, not where a linkage within it carries its joints (a four-bar of 1e9 links
// reaches 2e9), and Kennedy's lines stay far from overflow at any such size.
std::optional<Error> checkPoint(const Eigen::Vector2d& p, const std::string& name) {
  if (std::isfinite(p.x()) && std::isfinite(p.y())) return std::nullopt;
  return Error{ErrorCode::InvalidValue, name, name + " has no finite position, so the instant centres cannot be found"};
}

// Error if the two ends of a link coincide (the link has no direction there).
std::optional<Error> checkDistinct(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const std::string& what,
                                   double scale) {
  if ((b - a).norm() > kCentreTolerance * scale) return std::nullopt;
  return Error{ErrorCode::InvalidValue, what, what + " has coincident ends: its joints are at the same point"};
}

// Four bodies, every centre unresolved, ready for their primaries.
InstantCentres fourBodies(const char* third, const char* fourth, double scale, const Eigen::Vector2d& anchor,
                          RatioBodies ratio) {
  InstantCentres c;
  c.bodies = {"frame", "crank", third, fourth};
  c.centres.resize(6);
  c.origins.resize(6);
  c.scale = scale;
  c.anchor = anchor;
  c.ratio = ratio;
  return c;
}

void setPin(InstantCentres& c, std::size_t i, std::size_t j, const Eigen::Vector2d& at, const char* joint) {
  c.centres[c.pairIndex(i, j)] = {CentreKind::Finite, at, Eigen::Vector2d::Zero()};
  c.origins[c.pairIndex(i, j)] = {CentreRule::Pin, joint, at, {}};
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

// ωb/ωa for an output b turning about the frame pin I1b (the header's derivation).
Ratio turningRatio(const InstantCentres& c, const Eigen::Vector2d& i1a, const Eigen::Vector2d& i1b,
                   const InstantCentre& iab) {
  if (iab.kind == CentreKind::AtInfinity) return {RatioKind::Finite, 1.0};  // the two turn together
  const Eigen::Vector2d fromA = iab.position - i1a, fromB = iab.position - i1b;
  // Along the frame line; if the two pivots coincide, along the line the three centres share.
  Eigen::Vector2d e = i1b - i1a;
  if (e.norm() <= kCentreTolerance * c.scale) e = fromA.norm() >= fromB.norm() ? fromA : fromB;
  if (e.norm() <= kCentreTolerance * c.scale) return {RatioKind::Undefined, 0.0};  // all at one point
  e.normalize();
  return ratioOf(fromA.dot(e), fromB.dot(e), c.scale);
}

bool located(const InstantCentre& c) { return c.kind == CentreKind::Finite || c.kind == CentreKind::AtInfinity; }

}  // namespace

std::size_t InstantCentres::pairIndex(std::size_t i, std::size_t j) const {
  if (i > j) std::swap(i, j);
  const std::size_t n = bodyCount();
  return (i - 1) * n - (i - 1) * i / 2 + (j - i - 1);
}

Result<InstantCentres> fourBarInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& o4,
                                             const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  for (const auto& [p, name] : {std::pair{&o2, "O2"}, {&o4, "O4"}, {&b, "B"}, {&c, "C"}})
    if (auto e = checkPoint(*p, name)) return *e;
  const double scale = std::max({(b - o2).norm(), (c - b).norm(), (c - o4).norm(), (o4 - o2).norm()});
  for (const auto& [p, q, what] :
       {std::tuple{&o2, &o4, "frame"}, {&o2, &b, "crank"}, {&b, &c, "coupler"}, {&o4, &c, "rocker"}})
    if (auto e = checkDistinct(*p, *q, what, scale)) return *e;
  InstantCentres out = fourBodies("coupler", "rocker", scale, o2, {2, 4, false});
  setPin(out, 1, 2, o2, "O2");
  setPin(out, 1, 4, o4, "O4");
  setPin(out, 2, 3, b, "B");
  setPin(out, 3, 4, c, "C");
  completeByKennedy(out);
  return out;
}

Result<InstantCentres> sliderCrankInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& b,
                                                 const Eigen::Vector2d& c, const Eigen::Vector2d& guideDirection) {
  for (const auto& [p, name] : {std::pair{&o2, "O2"}, {&b, "B"}, {&c, "C"}, {&guideDirection, "guide direction"}})
    if (auto e = checkPoint(*p, name)) return *e;
  if (!(guideDirection.norm() > 0.0))
    return Error{ErrorCode::InvalidValue, "guide direction", "guide direction must not be zero"};
  const double scale = std::max((b - o2).norm(), (c - b).norm());
  for (const auto& [p, q, what] : {std::tuple{&o2, &b, "crank"}, {&b, &c, "rod"}})
    if (auto e = checkDistinct(*p, *q, what, scale)) return *e;
  InstantCentres out = fourBodies("rod", "slider C", scale, o2, {2, 4, true});
  out.outputDirection = guideDirection.normalized();
  setPin(out, 1, 2, o2, "O2");
  setPin(out, 2, 3, b, "B");
  setPin(out, 3, 4, c, "C");
  out.centres[out.pairIndex(1, 4)] = centreAtInfinity(perp(out.outputDirection));  // it translates on the guide
  out.origins[out.pairIndex(1, 4)] = {CentreRule::Slide, "C", c, {}};
  completeByKennedy(out);
  return out;
}

Result<InstantCentres> instantCentres(const Mechanism& m, const Pose& pose) {
  const auto model = centreModel(m);
  if (!model) return model.error();
  if (pose.position.size() != m.points.size())
    return Error{ErrorCode::InvalidStructure, "pose",
                 "the pose has " + std::to_string(pose.position.size()) + " points but the mechanism has " +
                     std::to_string(m.points.size())};
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (auto e = checkPoint(pose.position[i], m.points[i].name)) return *e;
  return instantCentres(m, *model, pose);
}

MechanicalAdvantage mechanicalAdvantage(const InstantCentres& c) {
  const Ratio undefined{RatioKind::Undefined, 0.0};
  MechanicalAdvantage out{undefined, undefined};
  if (!c.ratio.exists()) return out;
  const InstantCentre& i1a = c.centre(1, c.ratio.input);
  const InstantCentre& iab = c.centre(c.ratio.input, c.ratio.output);
  if (i1a.kind != CentreKind::Finite || !located(iab)) return out;
  if (!c.ratio.outputSlides) {
    const InstantCentre& i1b = c.centre(1, c.ratio.output);
    if (i1b.kind != CentreKind::Finite) return out;
    out.velocityRatio = turningRatio(c, i1a.position, i1b.position, iab);
  } else if (iab.kind == CentreKind::AtInfinity) {
    out.velocityRatio = {RatioKind::Infinite, 0.0};  // e.g. a slider-crank's rod normal to the guide
  } else {
    const double s = (iab.position - i1a.position).dot(perp(c.outputDirection));
    const bool atRest = std::abs(s) <= kCentreTolerance * c.scale;  // e.g. crank and rod in line
    out.velocityRatio = {RatioKind::Finite, atRest ? 0.0 : -s};
  }
  out.advantage = inverse(out.velocityRatio);
  return out;
}

}  // namespace linkwright::kinematics
