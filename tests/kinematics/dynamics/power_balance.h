#pragma once
// The power balance of a linkage at one pose, computed from the pose alone (not from the
// force solver's bodies): the driving power (a crank's T·ω2, an actuator's f·q̇, a path
// drive's F·v) plus the power of the external loads and of gravity equals the rate of change
// of kinetic energy Σ(m v_G·a_G + I ω α), since ideal joints do no work. The terms are the
// core's virtual work (virtual_work.h) with the pose's own velocities. Used to check
// inverse_dynamics.h on every sample of a sweep.

#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/dynamics/virtual_work.h"
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

/// The balance at `pose` for the driving power `drive` (W: drivePower, or T·ω2 for a crank):
/// the core's virtual work with the pose's own velocities (virtual_work.h).
inline PowerBalance powerBalance(const kinematics::Mechanism& m, const kinematics::LinkageDynamics& d,
                                 const kinematics::Pose& p, double drive) {
  const kinematics::VirtualWork w = kinematics::virtualWork(m, d, p, p);
  return {drive, w.loads, w.gravity, w.inertial, std::abs(drive) + w.scale};
}

}  // namespace linkwright::test
