#include "kinematics/solve/guide_line.h"

#include "kinematics/model/vec2.h"

#include <cmath>

namespace linkwright::kinematics {
GuideLine guideLineAt(const Mechanism& m, const Guide& guide, const Pose& pose) {
  if (!guide.link) return {guide.point, Eigen::Vector2d(std::cos(guide.angle), std::sin(guide.angle))};
  const Link& l = m.links[guide.link->index];
  const Eigen::Vector2d a = pose.position[l.first.index];
  const Eigen::Vector2d e = (pose.position[l.second.index] - a).normalized();
  const double c = std::cos(guide.angle);
  const double s = std::sin(guide.angle);
  return {a + guide.point.x() * e + guide.point.y() * perp(e), c * e + s * perp(e)};
}

double guideVelocityRhs(const Mechanism& m, const Guide& guide, const GuideLine& line, const Pose& pose,
                        const Eigen::Vector2d& c) {
  if (!guide.link) return 0.0;
  const std::size_t k = guide.link->index;
  const PointId a = m.links[k].first;
  const Eigen::Vector2d vP = pose.velocity[a.index] + pose.linkOmega[k] * perp(c - pose.position[a.index]);
  return guideNormal(line).dot(vP);
}

double guideAccelerationRhs(const Mechanism& m, const Guide& guide, const GuideLine& line, const Pose& pose,
                            const Eigen::Vector2d& c, const Eigen::Vector2d& vc) {
  if (!guide.link) return 0.0;
  const std::size_t k = guide.link->index;
  const PointId a = m.links[k].first;
  const double w = pose.linkOmega[k];
  const Eigen::Vector2d r = c - pose.position[a.index];
  const Eigen::Vector2d vP = pose.velocity[a.index] + w * perp(r);
  const Eigen::Vector2d aP = pose.acceleration[a.index] + pose.linkAlpha[k] * perp(r) - w * w * r;
  return guideNormal(line).dot(aP) + 2.0 * w * line.direction.dot(vc - vP);
}

}  // namespace linkwright::kinematics
