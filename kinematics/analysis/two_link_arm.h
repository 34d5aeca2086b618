#pragma once
// Inverse kinematics of a two-link (RR) planar arm, as in seed 004: the shoulder O at the
// origin, the upper link OA (length r1) and the forearm AB (r2); given where the tip B is and
// how it moves, find the links' angles, rates and accelerations. The elbow A is the RRR dyad
// point of circles r1 about O and r2 about B (rrr_dyad.h), so both elbow solutions come from
// the dyad's two branches. Angles are absolute, CCW from +x: θ1 of O→A, θ2 of A→B.
//
//   Velocity: vB = r1·ω1·e1⊥ + r2·ω2·e2⊥, a 2×2 system with det = r1·r2·sin(θ2 − θ1).
//   Acceleration: aB + r1·ω1²·e1 + r2·ω2²·e2 = r1·α1·e1⊥ + r2·α2·e2⊥, the same matrix.
// The arm is singular when stretched out or folded (θ2 = θ1 or θ1 + π): the tip is on the
// workspace boundary and cannot move outward; rates there are reported as undefined.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <vector>

namespace linkwright::kinematics {

struct TwoLinkArm {
  double upper = 0.0;    ///< r1, O to A
  double forearm = 0.0;  ///< r2, A to B
  bool operator==(const TwoLinkArm&) const = default;
};

/// Joint state for one tip state. Angles rad, rates rad/s, accelerations rad/s².
struct ArmState {
  double upperAngle = 0.0;    ///< θ1
  double forearmAngle = 0.0;  ///< θ2 (absolute)
  double upperOmega = 0.0;
  double forearmOmega = 0.0;
  double upperAlpha = 0.0;
  double forearmAlpha = 0.0;
  Eigen::Vector2d elbow = Eigen::Vector2d::Zero();  ///< A
  bool operator==(const ArmState&) const = default;
};

/// Solves the arm for tip position `p`, velocity `v`, acceleration `a`. Branch::Open puts the
/// elbow to the left of O→B (counter-clockwise side), Crossed to the right. Errors: invalid
/// lengths (field "upper"/"forearm"), a tip outside the workspace |r1 − r2| ≤ |p| ≤ r1 + r2
/// (NotAssemblable, with the distance), or a singular (stretched/folded) arm with a nonzero
/// velocity request (Singular).
Result<ArmState> solveTwoLinkArm(const TwoLinkArm& arm, Branch elbow, const Eigen::Vector2d& p,
                                 const Eigen::Vector2d& v = Eigen::Vector2d::Zero(),
                                 const Eigen::Vector2d& a = Eigen::Vector2d::Zero());

/// A straight tip path from `from` to `to` at constant `speed` (length unit per second).
struct LinePath {
  Eigen::Vector2d from = Eigen::Vector2d::Zero();
  Eigen::Vector2d to = Eigen::Vector2d::Zero();
  double speed = 1.0;
};

/// One sample along a path: time, tip position and the joint state (if it exists).
struct ArmSample {
  double time = 0.0;
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();
  bool reachable = false;
  ArmState state;
};

/// The arm along the path, `samples` evenly spaced in time (≥ 2). The path's time ranges that
/// leave the workspace come back in `unreachable` (start, end times, s), exactly: the line
/// meets the workspace circles |p| = r1 + r2 and |p| = |r1 − r2| at roots of a quadratic.
struct ArmPathResult {
  std::vector<ArmSample> samples;
  std::vector<std::pair<double, double>> unreachable;
};
Result<ArmPathResult> followLine(const TwoLinkArm& arm, Branch elbow, const LinePath& path, std::size_t samples);

/// Error naming the field unless the arm and its path lie in the input domain (validate.h):
/// link lengths, end points, a positive speed up to kMaxLength per second, and a largest
/// dimension at most kMaxLengthRatio times the shorter link.
std::optional<Error> checkArmPath(const TwoLinkArm& arm, const LinePath& path);

}  // namespace linkwright::kinematics
