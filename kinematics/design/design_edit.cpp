#include "kinematics/design/design_edit.h"

#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics {
Result<DragOutcome> dragFourBar(const FourBarDesign& design, double crankAngle, FourBarHandle handle,
                                const Eigen::Vector2d& target) {
  DragOutcome out{design, crankAngle, 0.0};
  FourBarLengths& l = out.design.lengths;
  const auto before = buildMechanism(design);
  if (!before) return before.error();
  const auto pose = solvePose(*before, {crankAngle, 0.0, 0.0}, {false, false});
  if (!pose) return pose.error();
  const Eigen::Vector2d b = pose->position[fourbar::kB.index];
  const Eigen::Vector2d c = pose->position[fourbar::kC.index];
  switch (handle) {
  case FourBarHandle::O2:
    l.frame = design.lengths.frame - target.x();
    out.originShift = target.x();
    break;
  case FourBarHandle::O4: l.frame = target.x(); break;
  case FourBarHandle::B:
    l.crank = target.norm();
    out.crankAngle = std::atan2(target.y(), target.x());
    break;
  case FourBarHandle::C: {
    const Eigen::Vector2d o4(design.lengths.frame, 0.0);
    l.coupler = (target - b).norm();
    l.rocker = (target - o4).norm();
    const double side = cross(target - b, target - o4);
    if (side != 0.0) out.design.branch = side > 0.0 ? Branch::Open : Branch::Crossed;
    break;
  }
  case FourBarHandle::CouplerPoint: {
    const Eigen::Vector2d u = (c - b).normalized();
    const Eigen::Vector2d n(-u.y(), u.x());
    out.design.couplerPoint = CouplerPointSpec{(target - b).dot(u), (target - b).dot(n)};
    break;
  }
  }
  const auto after = buildMechanism(out.design);
  if (!after) return after.error();
  const auto check = solvePose(*after, {out.crankAngle, 0.0, 0.0}, {false, false});
  if (!check && check.error().code == ErrorCode::NotAssemblable) return check.error();
  return out;
}

}  // namespace linkwright::kinematics
