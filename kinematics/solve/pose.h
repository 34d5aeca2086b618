#pragma once
// The request (what to compute, and how hard Newton tries for free points), the driver state
// (its input, rate and acceleration) and the pose (the solved state of every point and link at one input)
// that the pose solver fills.

#include "kinematics/model/ids.h"
#include "kinematics/solve/rrr_dyad.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// How Newton–Raphson solves free points (newton_group.h). The defaults close every distance
/// constraint to 1e-12 of the linkage's size, so Newton's poses agree with the closed-form
/// dyads' to about 1e-12 relative away from toggles.
struct NewtonSettings {
  /// Converged when every constraint's misfit, in length units (about |pa − pb| − L), is at
  /// most tolerance × the group's size: its longest constraint or its farthest point from the
  /// origin, whichever is larger (below ~1e-15 round-off alone exceeds it).
  double tolerance = 1e-12;
  /// Newton steps per free group and solve before it reports NoConvergence.
  int maxIterations = 50;
  bool operator==(const NewtonSettings&) const = default;
};

/// Which points and links a request reports: nullopt means all of them, an empty list none.
/// The solver computes the selected ones and whatever they are defined from (solve_scope.h),
/// nothing else: a plot of one six-bar link does not solve the rest of the linkage.
struct Selection {
  std::optional<std::vector<PointId>> points;
  std::optional<std::vector<LinkId>> links;
  bool operator==(const Selection&) const = default;
};

/// What to compute: positions always, rates if asked, of the selected points and links.
/// A scene computes only what it shows.
struct SolveRequest {
  bool velocities = true;     ///< ω of links, v of points
  bool accelerations = true;  ///< α of links, a of points (implies velocities)
  NewtonSettings newton{};    ///< for free points only
  Selection only{};           ///< default: every point and link
  /// Pose::transmissionAngle of dyad points (an atan2 each, about 10 % of a four-bar sample).
  bool transmissionAngles = true;
  bool operator==(const SolveRequest&) const = default;
};

/// The driver's state: its input q and the first two time derivatives (model/driver.h): a
/// crank's angle (rad, CCW from +x), ω (rad/s, CCW positive) and α (rad/s²); a linear
/// driver's position (length unit), speed and acceleration. A motion law gives one at every
/// instant (motion_law.h).
struct DriverState {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
  bool operator==(const DriverState&) const = default;
};

enum class PoseStatus {
  Ok,              ///< everything requested was computed
  Singular,        ///< positions are valid; a dyad (or free group) is at a toggle, so rates are undefined
  NotAssemblable,  ///< some point cannot be placed: see PoseReport::culprit and failure
};

/// How a solve went, and which point failed first.
struct PoseReport {
  PoseStatus status = PoseStatus::Ok;
  PointId culprit;  ///< the first point that failed (meaningful unless status is Ok)
  AssemblyFailure failure = AssemblyFailure::None;
  /// Newton steps taken for free points in this solve, all groups together (0 without them).
  int iterations = 0;
  /// The largest final constraint misfit of the free points (length unit; 0 without them).
  /// On NoConvergence: the misfit Newton was left with.
  double residual = 0.0;
  bool operator==(const PoseReport&) const = default;
};

/// The solved state, one entry per point and per link of the mechanism. Positions in the
/// mechanism's length unit; velocities per second, accelerations per second squared. Link
/// angles in (−π, π] rad, ω in rad/s, α in rad/s². Entries not requested stay zero.
struct Pose {
  std::vector<Eigen::Vector2d> position;
  std::vector<Eigen::Vector2d> velocity;
  std::vector<Eigen::Vector2d> acceleration;
  std::vector<double> linkAngle;
  std::vector<double> linkOmega;
  std::vector<double> linkAlpha;
  /// For RRR points: the transmission angle at C between C→P1 and C→P2, in [0, π]; for RRP
  /// points the angle between the rod and the guide's normal, in [0, π/2]; else 0.
  std::vector<double> transmissionAngle;
  /// For RRR and RRP points: how far the dyad is from an assembly limit (length unit): for RRR
  /// min(l1 + l2 − L, L − |l1 − l2|) with L the distance between its parents, for RRP the rod
  /// length less the pin's distance from the guide. 0 at a toggle; else 0.
  std::vector<double> assemblyGap;
  /// For RRR and RRP points: +1 open, −1 crossed, the branch actually used; else 0.
  std::vector<signed char> branchSign;
  /// True when `position` holds an assembled pose (set by solvePoseInto unless the result is
  /// NotAssemblable, cleared by preparePose). Free points start their next Newton solve from
  /// these positions: the previous sample of a sweep, the previous frame of a drag.
  bool assembled = false;
  bool operator==(const Pose&) const = default;
};

}  // namespace linkwright::kinematics
