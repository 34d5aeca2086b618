#include "kinematics/solve/rrp_dyad.h"

#include "kinematics/model/vec2.h"

#include <cmath>

namespace linkwright::kinematics {

RrpCandidates rrpCandidates(const Eigen::Vector2d& p1, double length, const Eigen::Vector2d& guidePoint,
                            const Eigen::Vector2d& guideDirection) {
  RrpCandidates out;
  const Eigen::Vector2d d = guidePoint - p1;
  const double b = guideDirection.dot(d);
  // The distance from P1 to the guide, computed directly rather than from b² − c, so the
  // discriminant near the toggle carries no cancellation: b² − c = l² − distance².
  const double distance = std::abs(cross(guideDirection, d));
  out.reachGap = length - distance;
  if (out.reachGap < -kAssemblyTolerance * length) {
    out.failure = AssemblyFailure::TooFar;
    return out;
  }
  const double root = std::sqrt(std::max(0.0, (length - distance) * (length + distance)));
  out.open = -b + root;
  out.crossed = -b - root;
  out.reachGap = std::max(0.0, out.reachGap);
  return out;
}

bool rrpSolveRate(const Eigen::Vector2d& r, const Eigen::Vector2d& guideDirection, double rhs, double& rate) {
  const double along = r.dot(guideDirection);
  if (!(std::abs(along) > kSingularSine * r.norm())) return false;
  rate = rhs / along;
  return true;
}

}  // namespace linkwright::kinematics
