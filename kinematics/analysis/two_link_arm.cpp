#include "kinematics/analysis/two_link_arm.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/rrr_dyad.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

// Solves [r1·e1⊥  r2·e2⊥] x = rhs; false when the arm is stretched or folded.
bool solveJoints(double r1, const Eigen::Vector2d& e1, double r2, const Eigen::Vector2d& e2, const Eigen::Vector2d& rhs,
                 double& x1, double& x2) {
  const Eigen::Vector2d c1 = r1 * perp(e1);
  const Eigen::Vector2d c2 = r2 * perp(e2);
  const double det = cross(c1, c2);
  if (!(std::abs(det) > kSingularSine * r1 * r2)) return false;
  x1 = (rhs.x() * c2.y() - c2.x() * rhs.y()) / det;
  x2 = (c1.x() * rhs.y() - rhs.x() * c1.y()) / det;
  return true;
}

// Times t in [0, T] where |from + t·u·speed| crosses radius R: roots of a quadratic in t.
std::vector<double> circleCrossings(const LinePath& path, double duration, double radius) {
  const Eigen::Vector2d d = path.to - path.from;
  const Eigen::Vector2d vel = d / duration;
  const double a = vel.squaredNorm();
  const double b = 2.0 * path.from.dot(vel);
  const double c = path.from.squaredNorm() - radius * radius;
  const double disc = b * b - 4.0 * a * c;
  std::vector<double> out;
  if (disc <= 0.0) return out;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));  // stable roots
  for (const double t : {q / a, c / q})
    if (t > 0.0 && t < duration) out.push_back(t);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

Result<ArmState> solveTwoLinkArm(const TwoLinkArm& arm, Branch elbow, const Eigen::Vector2d& p,
                                 const Eigen::Vector2d& v, const Eigen::Vector2d& a) {
  if (auto e = checkLength(arm.upper, "upper")) return *e;
  if (auto e = checkLength(arm.forearm, "forearm")) return *e;
  const RrrCandidates c = rrrCandidates(Eigen::Vector2d::Zero(), arm.upper, p, arm.forearm);
  if (c.failure != AssemblyFailure::None)
    return Error{ErrorCode::NotAssemblable, "tip",
                 "the tip at (" + kinematics::formatShort(p.x()) + ", " + kinematics::formatShort(p.y()) + ") is " +
                     kinematics::formatShort(p.norm()) + " from the shoulder, outside the workspace " +
                     kinematics::formatShort(std::abs(arm.upper - arm.forearm)) + " to " +
                     kinematics::formatShort(arm.upper + arm.forearm)};
  ArmState s;
  s.elbow = elbow == Branch::Open ? c.open : c.crossed;
  const Eigen::Vector2d e1 = s.elbow / arm.upper;
  const Eigen::Vector2d e2 = (p - s.elbow) / arm.forearm;
  s.upperAngle = std::atan2(e1.y(), e1.x());
  s.forearmAngle = std::atan2(e2.y(), e2.x());
  if (v.isZero() && a.isZero()) return s;
  if (!solveJoints(arm.upper, e1, arm.forearm, e2, v, s.upperOmega, s.forearmOmega))
    return Error{ErrorCode::Singular, "tip",
                 "the arm is stretched out or folded at (" + kinematics::formatShort(p.x()) + ", " +
                     kinematics::formatShort(p.y()) +
                     "): the tip cannot move in every direction there, so joint rates are undefined"};
  const Eigen::Vector2d rhs =
      a + arm.upper * s.upperOmega * s.upperOmega * e1 + arm.forearm * s.forearmOmega * s.forearmOmega * e2;
  solveJoints(arm.upper, e1, arm.forearm, e2, rhs, s.upperAlpha, s.forearmAlpha);
  return s;
}

std::optional<Error> checkArmPath(const TwoLinkArm& arm, const LinePath& path) {
  if (auto e = checkLength(arm.upper, "upper")) return e;
  if (auto e = checkLength(arm.forearm, "forearm")) return e;
  if (!(std::isfinite(path.speed) && path.speed > 0.0))
    return Error{ErrorCode::InvalidValue, "speed",
                 "speed must be positive and finite (got " + formatNumber(path.speed) + ")"};
  if (auto e = checkMagnitude(path.speed, "speed", kMaxLength, "length units/s")) return e;
  for (const auto& [point, name] : {std::pair{path.from, "from"}, {path.to, "to"}}) {
    if (auto e = checkCoordinate(point.x(), std::string(name) + ".x")) return e;
    if (auto e = checkCoordinate(point.y(), std::string(name) + ".y")) return e;
  }
  const double reach =
      std::max({arm.upper, arm.forearm, path.from.cwiseAbs().maxCoeff(), path.to.cwiseAbs().maxCoeff()});
  return checkScale(std::min(arm.upper, arm.forearm), "the shorter arm link", reach, "the arm's largest dimension",
                    "length units");
}

Result<ArmPathResult> followLine(const TwoLinkArm& arm, Branch elbow, const LinePath& path, std::size_t samples) {
  if (auto e = checkArmPath(arm, path)) return *e;
  const double length = (path.to - path.from).norm();
  if (!(length > 0.0)) return Error{ErrorCode::InvalidValue, "path", "path must have distinct end points"};
  if (samples < 2)
    return Error{ErrorCode::InvalidValue, "samples",
                 "samples must be at least 2 (got " + std::to_string(samples) + ")"};
  const double duration = length / path.speed;
  const Eigen::Vector2d velocity = (path.to - path.from) / duration;
  ArmPathResult out;
  out.samples.reserve(samples);
  for (std::size_t j = 0; j < samples; ++j) {
    ArmSample s;
    s.time = duration * static_cast<double>(j) / static_cast<double>(samples - 1);
    s.tip = path.from + velocity * s.time;
    const auto state = solveTwoLinkArm(arm, elbow, s.tip, velocity);
    s.reachable = state.ok();
    if (state) s.state = *state;
    out.samples.push_back(s);
  }
  // Exact unreachable intervals: split the path where it crosses a workspace circle and test
  // each piece's midpoint.
  std::vector<double> cuts{0.0};
  for (const double radius : {arm.upper + arm.forearm, std::abs(arm.upper - arm.forearm)})
    for (const double t : circleCrossings(path, duration, radius)) cuts.push_back(t);
  cuts.push_back(duration);
  std::sort(cuts.begin(), cuts.end());
  const double inner = std::abs(arm.upper - arm.forearm), outer = arm.upper + arm.forearm;
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double mid = (path.from + velocity * 0.5 * (cuts[k] + cuts[k + 1])).norm();
    if (mid >= inner && mid <= outer) continue;
    if (!out.unreachable.empty() && out.unreachable.back().second == cuts[k])
      out.unreachable.back().second = cuts[k + 1];
    else out.unreachable.emplace_back(cuts[k], cuts[k + 1]);
  }
  return out;
}

}  // namespace linkwright::kinematics
