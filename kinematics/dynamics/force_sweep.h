#pragma once
// Inverse dynamics over a sweep: the forces of inverse_dynamics.h at every sample of a
// kinematic sweep (sweep.h), stored one column per quantity like SweepResult, for the CSV
// columns, the plots and the polar load diagrams. The driver's rates are the sweep's, so a
// sweep with α ≠ 0 (or on a time base) gives the forces of an accelerating crank, cylinder or
// path drive. A crank's driving torque is also found by virtual work, the independent check
// every table carries beside it.

#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/rigid_bodies.h"
#include "kinematics/solve/sweep.h"

#include <Eigen/Core>

#include <atomic>
#include <vector>

namespace linkwright::kinematics {

/// Forces over a sweep. Outer index: joint (as in `bodies`); inner index: sample. Samples
/// whose status is not Ok hold 0: a sample the kinematics could not assemble or flagged
/// singular keeps the sweep's status, and a sample where the forces are not determined is
/// Singular.
struct ForceSweep {
  BodyModel bodies;                                    ///< names the joints the columns belong to
  std::vector<PoseStatus> status;                      ///< per sample
  std::vector<std::vector<Eigen::Vector2d>> revolute;  ///< N, force on joint.body from joint.hub
  std::vector<std::vector<double>> normal;             ///< N, per prismatic joint (PoseForces::normal)
  std::vector<std::vector<double>> moment;             ///< N·m, per prismatic joint
  std::vector<double> driveTorque;                     ///< N·m, a crank's, on the driven body, CCW +
  std::vector<double> virtualWorkTorque;               ///< N·m, a crank's by virtual work (virtual_work.h)
  std::vector<double> driveAlong;                      ///< N, a linear driver's along its input (PoseForces)
  std::vector<Eigen::Vector2d> driveForce;             ///< N, a linear driver's on the driven body
  std::vector<Eigen::Vector2d> jointTorque;            ///< N·m, a serial arm's shoulder (x) and elbow (y)
  std::vector<Eigen::Vector2d> shakingForce;           ///< N, on the frame
  std::vector<double> shakingMoment;                   ///< N·m, about bodies.momentPoint (the crank pivot)

  std::size_t size() const { return status.size(); }
  bool ok(std::size_t sample) const { return status[sample] == PoseStatus::Ok; }
  /// The forces of one sample as a PoseForces (zeros where not ok).
  PoseForces at(std::size_t sample) const;
};

/// Solves the forces at every sample of `sweep`, which must come from sweep(mechanism, …)
/// with accelerations requested (an error otherwise, as for an invalid mechanism, dynamics
/// or length unit: see InverseDynamics::create). Each sample's input (inputAngle) is the
/// driver's coordinate a path drive's tangent is taken at. If `cancel` is given and becomes
/// true (another thread sets it), the solve stops at the next sample with ErrorCode::Cancelled.
Result<ForceSweep> sweepForces(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepResult& sweep,
                               const std::atomic<bool>* cancel = nullptr);

}  // namespace linkwright::kinematics
