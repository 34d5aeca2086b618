#pragma once
// The columns a force sweep (force_sweep.h) is tabulated in, each named with its unit, for the
// CSV writer, the CLI's text table and the GUI's plots, as sweep_columns.h does for kinematics:
//   F_<joint>_x_N, F_<joint>_y_N, F_<joint>_N   each revolute joint: the force its hub body
//                                               exerts on its other body (at a ground pivot, the
//                                               ground on the link), world frame, and its size
//   N_<joint>_N, M_<joint>_Nm                   each prismatic joint: the guide body's normal
//                                               force (along the guide's normal, its direction
//                                               turned 90° CCW) and couple on the block
//   the driver's generalized force, by driver:
//     T_drive_Nm                                a crank: the motor torque on it, CCW positive
//     T_drive_virtual_work_Nm,                  the same by virtual work (virtual_work.h), and
//     T_drive_difference_Nm                     Newton–Euler less virtual work: round-off
//     actuator_force_N                          a linear actuator: its axial force, positive
//                                               pushing its end away from its base
//     <point>_drive_fx_N, <point>_drive_fy_N,   a point driven along a path: the drive's force
//     <point>_drive_force_N                     on it (world frame; the guide's reaction
//                                               included), and its part along the path's
//                                               tangent, positive toward increasing s
//   <pivot>_joint_torque_Nm,                    a path drive at the tip of a two-link arm: the
//   <elbow>_joint_torque_Nm                     shoulder and elbow torques that move the arm the
//                                               same way with its tip free (τ = JᵀF), CCW positive
//   shaking_x_N, shaking_y_N, shaking_N         the force the linkage exerts on its frame
//   shaking_moment_Nm                           its moment about the crank pivot (with the motor's
//                                               reaction), or for other drivers about the first
//                                               ground point
// Joint names are rigid_bodies.h's: the point's name, with the body's when a point holds
// several joints, and _<rpr point> or _1/_2 for slider blocks.

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/solve/rigid_bodies.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

enum class ForceQuantity {
  JointX,
  JointY,
  JointMagnitude,
  Normal,
  Moment,
  DriveTorque,
  VirtualWorkTorque,
  VirtualWorkDifference,
  DriveAlong,
  DriveX,
  DriveY,
  JointTorque,
  ShakingX,
  ShakingY,
  ShakingMagnitude,
  ShakingMoment,
};

/// One force column: what it holds and of which joint (`index` into the model's revolutes or
/// prismatics; for JointTorque 0 the shoulder, 1 the elbow).
struct ForceColumn {
  std::string name;  ///< e.g. "F_O2_x_N"
  ForceQuantity quantity = ForceQuantity::DriveTorque;
  std::size_t index = 0;
  bool operator==(const ForceColumn&) const = default;

  /// The value at `sample` in N or N·m (0 where the sample is not ok: check first).
  double value(const ForceSweep& forces, std::size_t sample) const;
  /// True for sizes, the driver's generalized force and joint torques: the columns of a short table.
  bool isSummary() const;
};

/// All force columns of a model, in CSV order.
std::vector<ForceColumn> forceColumns(const BodyModel& bodies);

}  // namespace linkwright::kinematics
