#include "kinematics/analysis/centrodes.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/recognise.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace linkwright::kinematics {

namespace {

// The coupler's joints B and C, from whichever structure the mechanism has.
struct CouplerJoints {
  PointId b, c;
};

Result<CouplerJoints> couplerJoints(const Mechanism& mechanism) {
  if (const auto fourBar = asFourBar(mechanism, PointsOnLinks::AnyLink)) return CouplerJoints{fourBar->b, fourBar->c};
  if (const auto slider = asSliderCrank(mechanism, PointsOnLinks::AnyLink)) return CouplerJoints{slider->b, slider->c};
  return Error{ErrorCode::InvalidStructure, "mechanism",
               "centrodes are drawn for a four-bar or a slider-crank only (Kennedy's theorem locates their "
               "coupler's centre)"};
}

CouplerFrame frameAt(const CouplerJoints& joints, const Pose& pose) {
  const Eigen::Vector2d b = pose.position[joints.b.index], c = pose.position[joints.c.index];
  return CouplerFrame{b, std::atan2(c.y() - b.y(), c.x() - b.x())};
}

}  // namespace

Eigen::Vector2d CouplerFrame::toWorld(const Eigen::Vector2d& local) const {
  const double c = std::cos(angle), s = std::sin(angle);
  return b + Eigen::Vector2d(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}

Eigen::Vector2d CouplerFrame::toLocal(const Eigen::Vector2d& world) const {
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector2d d = world - b;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

Result<CouplerFrame> couplerFrame(const Mechanism& mechanism, const Pose& pose) {
  const auto joints = couplerJoints(mechanism);
  if (!joints) return joints.error();
  return frameAt(*joints, pose);
}

Result<Centrodes> centrodes(const Mechanism& mechanism, const SweepResult& sweep) {
  const auto joints = couplerJoints(mechanism);
  if (!joints) return joints.error();
  const bool complete = sweep.position.size() == mechanism.points.size() &&
                        std::all_of(sweep.position.begin(), sweep.position.end(),
                                    [&](const auto& column) { return column.size() >= sweep.size(); });
  if (!complete)
    return Error{ErrorCode::InvalidValue, "sweep", "centrodes need every point's position at every sample"};
  Centrodes out;
  bool inRun = false;
  Pose pose;  // positions only: the centres need nothing else
  pose.position.resize(mechanism.points.size());
  for (std::size_t j = 0; j < sweep.size(); ++j) {
    std::optional<Eigen::Vector2d> centre;
    if (sweep.assembled(j)) {
      for (std::size_t i = 0; i < pose.position.size(); ++i) pose.position[i] = sweep.position[i][j];
      const auto centres = instantCentres(mechanism, pose);
      if (!centres) return centres.error();
      const InstantCentre& i13 = centres->i13;
      if (i13.kind == CentreKind::Finite &&
          (i13.position - centres->i12.position).norm() <= kCentrodeReach * centres->scale)
        centre = i13.position;
    }
    if (!centre) {
      inRun = false;
      continue;
    }
    if (!inRun) {
      out.fixed.emplace_back();
      out.moving.emplace_back();
      inRun = true;
    }
    out.fixed.back().push_back(*centre);
    out.moving.back().push_back(frameAt(*joints, pose).toLocal(*centre));
  }
  return out;
}

}  // namespace linkwright::kinematics
