#pragma once
// The power balance of a linkage at one pose, computed from the pose alone (not from the
// force solver's bodies): the driving power (a crank's T·ω2, an actuator's f·q̇, a path
// drive's F·v) plus the power of the external loads and of gravity equals the rate of change
// of kinetic energy Σ(m v_G·a_G + I ω α), since ideal joints do no work. Used to check
// inverse_dynamics.h on every sample of a sweep.

#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/rigid_bodies.h"

#include <Eigen/Core>

#include <cmath>
#include <optional>
#include <utility>

namespace linkwright::test {

/// The terms of the balance (W), and the sum of their magnitudes (the scale of a residual).
struct PowerBalance {
  double drive = 0.0;    ///< T·ω2, f·q̇ or F·v
  double loads = 0.0;    ///< Σ T_L·ω + Σ F·v
  double gravity = 0.0;  ///< Σ m g·v_G
  double kinetic = 0.0;  ///< dE/dt = Σ (m v_G·a_G + I ω α)
  double scale = 0.0;

  double residual() const { return drive + loads + gravity - kinetic; }
};

namespace detail {

// ω and α of the body a slider block turns with, read from the pose's links, or for a slotted
// link from its pivot and tip (two points of one rigid body).
inline std::pair<double, double> blockRates(const kinematics::Mechanism& m, const kinematics::SliderKey& key,
                                            const kinematics::Pose& p) {
  using namespace kinematics;
  const PointDefinition& def = m.points[key.point.index].definition;
  std::optional<LinkId> link;
  if (const auto* rrp = std::get_if<RrpPoint>(&def)) link = rrp->guide.link;
  else if (const auto* q = std::get_if<PrpPoint>(&def)) link = (key.guide == 0 ? q->first : q->second).link;
  else {
    const std::size_t tip = key.point.index;
    const std::size_t pivot = std::get<RprPoint>(def).pivot.index;
    const Eigen::Vector2d r = p.position[tip] - p.position[pivot];
    return {cross(r, p.velocity[tip] - p.velocity[pivot]) / r.squaredNorm(),
            cross(r, p.acceleration[tip] - p.acceleration[pivot]) / r.squaredNorm()};
  }
  if (!link) return {0.0, 0.0};
  return {p.linkOmega[link->index], p.linkAlpha[link->index]};
}

inline kinematics::PointId blockPin(const kinematics::Mechanism& m, kinematics::PointId point) {
  if (const auto* s = std::get_if<kinematics::RprPoint>(&m.points[point.index].definition)) return s->through;
  return point;
}

}  // namespace detail

/// The driving power (W) at `p` of the forces `f` solved for it, from the pose's rates: the
/// crank's T times its ω (tip about pivot), the actuator's f times its rate of extension
/// u·(v_C − v_base), the path drive's F·v_P.
inline double drivePower(const kinematics::Mechanism& m, const kinematics::Pose& p, const kinematics::PoseForces& f) {
  using namespace kinematics;
  const double s = *metresPerLengthUnit(m.lengthUnit);
  const std::size_t point = driverPoint(m)->index;
  const PointDefinition& def = m.points[point].definition;
  if (const auto* c = std::get_if<CrankPoint>(&def)) {
    const Eigen::Vector2d r = p.position[point] - p.position[c->pivot.index];
    return f.driveTorque * cross(r, p.velocity[point] - p.velocity[c->pivot.index]) / r.squaredNorm();
  }
  if (const auto* a = std::get_if<ActuatorPoint>(&def)) {
    const Eigen::Vector2d u = (p.position[point] - p.position[a->base.index]).normalized();
    return f.driveAlong * u.dot(s * (p.velocity[point] - p.velocity[a->base.index]));
  }
  return f.driveForce.dot(s * p.velocity[point]);
}

/// The balance at `pose` for the driving power `drive` (W: drivePower, or T·ω2 for a crank).
inline PowerBalance powerBalance(const kinematics::Mechanism& m, const kinematics::LinkageDynamics& d,
                                 const kinematics::Pose& p, double drive) {
  using namespace kinematics;
  const double s = *metresPerLengthUnit(m.lengthUnit);
  const Eigen::Vector2d g = d.loads.gravity.value_or(Eigen::Vector2d::Zero());
  PowerBalance b;
  b.drive = drive;
  b.scale = std::abs(b.drive);
  auto addMass = [&](double mass, double inertia, double w, double alpha, const Eigen::Vector2d& v,
                     const Eigen::Vector2d& a) {
    const double kinetic = mass * v.dot(a) + inertia * w * alpha;
    b.kinetic += kinetic;
    b.gravity += mass * g.dot(v);
    b.scale += std::abs(mass * v.dot(a)) + std::abs(inertia * w * alpha) + std::abs(mass * g.dot(v));
  };
  for (const LinkMass& l : d.links) {
    const LinkId k = *m.findLink(l.link);
    const Link& link = m.links[k.index];
    const Eigen::Vector2d a = s * p.position[link.first.index];
    const Eigen::Vector2d e = s * p.position[link.second.index] - a;
    const double length = e.norm();
    const Eigen::Vector2d u = e / length;
    const LinkFramePoint c = l.centre.value_or(LinkFramePoint{0.5 * length / s, 0.0});
    const Eigen::Vector2d r = s * (c.along * u + c.across * kinematics::perp(u));
    const double w = p.linkOmega[k.index];
    const double alpha = p.linkAlpha[k.index];
    const Eigen::Vector2d v = s * p.velocity[link.first.index] + w * kinematics::perp(r);
    const Eigen::Vector2d acc = s * p.acceleration[link.first.index] + alpha * kinematics::perp(r) - w * w * r;
    addMass(l.mass, l.inertia.value_or(l.mass * length * length / 12.0), w, alpha, v, acc);
  }
  for (const SliderMass& sm : d.sliders) {
    const SliderKey key{*m.findPoint(sm.point), sm.guide};
    const PointId pin = detail::blockPin(m, key.point);
    const auto [w, alpha] = detail::blockRates(m, key, p);
    addMass(sm.mass, sm.inertia, w, alpha, s * p.velocity[pin.index], s * p.acceleration[pin.index]);
  }
  for (const LinkTorque& t : d.loads.torques) {
    const double power = t.torque * p.linkOmega[m.findLink(t.link)->index];
    b.loads += power;
    b.scale += std::abs(power);
  }
  for (const PointForce& f : d.loads.forces) {
    const PointId at = f.link.empty() ? detail::blockPin(m, *m.findPoint(f.point)) : *m.findPoint(f.point);
    const double power = f.force.dot(s * p.velocity[at.index]);
    b.loads += power;
    b.scale += std::abs(power);
  }
  return b;
}

}  // namespace linkwright::test
