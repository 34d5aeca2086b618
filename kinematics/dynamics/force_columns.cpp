#include "kinematics/dynamics/force_columns.h"

namespace linkwright::kinematics {

double ForceColumn::value(const ForceSweep& f, std::size_t j) const {
  switch (quantity) {
  case ForceQuantity::JointX: return f.revolute[index][j].x();
  case ForceQuantity::JointY: return f.revolute[index][j].y();
  case ForceQuantity::JointMagnitude: return f.revolute[index][j].norm();
  case ForceQuantity::Normal: return f.normal[index][j];
  case ForceQuantity::Moment: return f.moment[index][j];
  case ForceQuantity::DriveTorque: return f.driveTorque[j];
  case ForceQuantity::VirtualWorkTorque: return f.virtualWorkTorque[j];
  case ForceQuantity::VirtualWorkDifference: return f.driveTorque[j] - f.virtualWorkTorque[j];
  case ForceQuantity::DriveAlong: return f.driveAlong[j];
  case ForceQuantity::DriveX: return f.driveForce[j].x();
  case ForceQuantity::DriveY: return f.driveForce[j].y();
  case ForceQuantity::JointTorque: return f.jointTorque[j][static_cast<Eigen::Index>(index)];
  case ForceQuantity::ShakingX: return f.shakingForce[j].x();
  case ForceQuantity::ShakingY: return f.shakingForce[j].y();
  case ForceQuantity::ShakingMagnitude: return f.shakingForce[j].norm();
  case ForceQuantity::ShakingMoment: return f.shakingMoment[j];
  }
  return 0.0;
}

bool ForceColumn::isSummary() const {
  return quantity == ForceQuantity::JointMagnitude || quantity == ForceQuantity::Normal ||
         quantity == ForceQuantity::DriveTorque || quantity == ForceQuantity::DriveAlong ||
         quantity == ForceQuantity::JointTorque || quantity == ForceQuantity::ShakingMagnitude;
}

std::vector<ForceColumn> forceColumns(const BodyModel& bodies) {
  using Q = ForceQuantity;
  std::vector<ForceColumn> columns;
  for (std::size_t k = 0; k < bodies.revolutes.size(); ++k) {
    const std::string& joint = bodies.revolutes[k].name;
    columns.push_back({"F_" + joint + "_x_N", Q::JointX, k});
    columns.push_back({"F_" + joint + "_y_N", Q::JointY, k});
    columns.push_back({"F_" + joint + "_N", Q::JointMagnitude, k});
  }
  for (std::size_t k = 0; k < bodies.prismatics.size(); ++k) {
    const std::string& joint = bodies.prismatics[k].name;
    columns.push_back({"N_" + joint + "_N", Q::Normal, k});
    columns.push_back({"M_" + joint + "_Nm", Q::Moment, k});
  }
  const Drive& drive = bodies.drive;
  switch (drive.kind) {
  case DriveKind::Crank:
    columns.push_back({"T_drive_Nm", Q::DriveTorque, 0});
    columns.push_back({"T_drive_virtual_work_Nm", Q::VirtualWorkTorque, 0});
    columns.push_back({"T_drive_difference_Nm", Q::VirtualWorkDifference, 0});
    break;
  case DriveKind::Actuator: columns.push_back({"actuator_force_N", Q::DriveAlong, 0}); break;
  case DriveKind::Path:
    columns.push_back({drive.name + "_drive_fx_N", Q::DriveX, 0});
    columns.push_back({drive.name + "_drive_fy_N", Q::DriveY, 0});
    columns.push_back({drive.name + "_drive_force_N", Q::DriveAlong, 0});
    break;
  }
  if (bodies.arm) {
    columns.push_back({bodies.arm->pivotName + "_joint_torque_Nm", Q::JointTorque, 0});
    columns.push_back({bodies.arm->elbowName + "_joint_torque_Nm", Q::JointTorque, 1});
  }
  columns.push_back({"shaking_x_N", Q::ShakingX, 0});
  columns.push_back({"shaking_y_N", Q::ShakingY, 0});
  columns.push_back({"shaking_N", Q::ShakingMagnitude, 0});
  columns.push_back({"shaking_moment_Nm", Q::ShakingMoment, 0});
  return columns;
}

}  // namespace linkwright::kinematics
