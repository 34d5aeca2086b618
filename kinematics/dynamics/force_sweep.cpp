#include "kinematics/dynamics/force_sweep.h"

#include "kinematics/dynamics/virtual_work.h"
#include "kinematics/solve/pose_solver.h"

#include <optional>

#include <string>

namespace linkwright::kinematics {
namespace {

// Every point and link column holds every sample (a sweep of a selection leaves some empty).
bool hasAllColumns(const Mechanism& m, const SweepResult& s) {
  const auto full = [&](const auto& columns, std::size_t count) {
    if (columns.size() != count) return false;
    for (const auto& column : columns)
      if (column.size() != s.size()) return false;
    return true;
  };
  return full(s.position, m.points.size()) && full(s.velocity, m.points.size()) &&
         full(s.acceleration, m.points.size()) && full(s.linkAngle, m.links.size()) &&
         full(s.linkOmega, m.links.size()) && full(s.linkAlpha, m.links.size());
}

void allocate(ForceSweep& out, std::size_t samples) {
  out.status.assign(samples, PoseStatus::Ok);
  out.revolute.assign(out.bodies.revolutes.size(), std::vector<Eigen::Vector2d>(samples, Eigen::Vector2d::Zero()));
  out.normal.assign(out.bodies.prismatics.size(), std::vector<double>(samples, 0.0));
  out.moment.assign(out.bodies.prismatics.size(), std::vector<double>(samples, 0.0));
  out.driveTorque.assign(samples, 0.0);
  out.virtualWorkTorque.assign(samples, 0.0);
  out.driveAlong.assign(samples, 0.0);
  out.driveForce.assign(samples, Eigen::Vector2d::Zero());
  out.jointTorque.assign(samples, Eigen::Vector2d::Zero());
  out.shakingForce.assign(samples, Eigen::Vector2d::Zero());
  out.shakingMoment.assign(samples, 0.0);
}

void store(const PoseForces& f, std::size_t j, ForceSweep& out) {
  for (std::size_t k = 0; k < f.revolute.size(); ++k) out.revolute[k][j] = f.revolute[k];
  for (std::size_t k = 0; k < f.normal.size(); ++k) {
    out.normal[k][j] = f.normal[k];
    out.moment[k][j] = f.moment[k];
  }
  out.driveTorque[j] = f.driveTorque;
  out.driveAlong[j] = f.driveAlong;
  out.driveForce[j] = f.driveForce;
  out.jointTorque[j] = f.jointTorque;
  out.shakingForce[j] = f.shakingForce;
  out.shakingMoment[j] = f.shakingMoment;
}

}  // namespace

PoseForces ForceSweep::at(std::size_t j) const {
  PoseForces f;
  for (const auto& column : revolute) f.revolute.push_back(column[j]);
  for (const auto& column : normal) f.normal.push_back(column[j]);
  for (const auto& column : moment) f.moment.push_back(column[j]);
  f.driveTorque = driveTorque[j];
  f.driveAlong = driveAlong[j];
  f.driveForce = driveForce[j];
  f.jointTorque = jointTorque[j];
  f.shakingForce = shakingForce[j];
  f.shakingMoment = shakingMoment[j];
  return f;
}

Result<ForceSweep> sweepForces(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepResult& sweep,
                               const std::atomic<bool>* cancel) {
  if (!sweep.request.accelerations)
    return Error{ErrorCode::InvalidValue, "request.accelerations",
                 "forces need a sweep with accelerations (request.accelerations was off): inertia forces are m·a"};
  auto solver = InverseDynamics::create(mechanism, dynamics);
  if (!solver) return solver.error();
  InverseDynamics& solve = solver.value();
  if (!hasAllColumns(mechanism, sweep))
    return Error{ErrorCode::InvalidStructure, "sweep",
                 "forces need every point and link of the mechanism solved at every sample (this sweep's columns "
                 "do not match the mechanism, or it solved a selection only)"};
  ForceSweep out;
  out.bodies = solve.bodies();
  allocate(out, sweep.size());
  Pose pose;
  preparePose(mechanism, pose);
  PoseForces forces;
  solve.prepare(forces);
  std::optional<CrankVirtualWork> virtualWork;
  if (out.bodies.drive.kind == DriveKind::Crank) {
    auto created = CrankVirtualWork::create(mechanism, dynamics);
    if (!created) return created.error();
    virtualWork.emplace(std::move(created.value()));
  }
  for (std::size_t j = 0; j < sweep.size(); ++j) {
    if (cancel != nullptr && cancel->load(std::memory_order_relaxed))
      return Error{ErrorCode::Cancelled, "forces", "the force solve was cancelled at sample " + std::to_string(j)};
    if (!sweep.ok(j)) {
      out.status[j] = sweep.report[j].status;
      continue;
    }
    copySampleToPose(sweep, j, pose);
    out.status[j] = solve.solveInto(pose, forces, sweep.inputAngle[j]);
    if (out.status[j] != PoseStatus::Ok) continue;
    store(forces, j, out);
    if (virtualWork) out.virtualWorkTorque[j] = virtualWork->torque(pose, sweep.inputAngle[j]);
  }
  return out;
}

}  // namespace linkwright::kinematics
