#pragma once
// Solves a Mechanism at one driver state by running its points in order: ground pivots, the
// crank tip (B = O + l·(cos φ, sin φ), φ = input angle + phase), RRR dyads in closed form
// (see rrr_dyad.h) and points fixed on links. Link rates follow exactly from their end
// points: for a rigid link r = P2 − P1, ω = r×(v2−v1)/|r|² and α = r×(a2−a1)/|r|².
// Nothing here differentiates numerically.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"
#include "kinematics/solve/solve_scope.h"

#include <span>
#include <string>

namespace linkwright::kinematics {

/// Optional steering of the branch choice, used by the sweep to track branches continuously.
struct BranchGuide {
  /// Per point: +1/−1 overrides an RRR point's branch; empty means use the mechanism's.
  std::span<const signed char> signs;
  /// Per point: when non-empty, each RRR point takes the candidate nearest this position.
  std::span<const Eigen::Vector2d> predicted;
};

/// Sizes `pose` for `mechanism` (call once; solvePoseInto then never allocates) and places
/// its ground pivots, which a scoped solve (solve_scope.h) does not touch again.
void preparePose(const Mechanism& mechanism, Pose& pose);

/// Solves into a prepared pose. Assumes checkMechanism passed. Never throws or allocates.
/// With a `scope` (built from request.only by scopeOf), only the points and links in it are
/// solved (the ground pivots are where preparePose put them); entries outside it keep whatever
/// they held. Without one, everything is solved.
PoseReport solvePoseInto(const Mechanism& mechanism, const DriverState& driver, const SolveRequest& request, Pose& pose,
                         const BranchGuide& guide = {}, const SolveScope* scope = nullptr);

/// The most poses solveBlockInto solves at once.
inline constexpr std::size_t kMaxBlock = 8;

/// Solves up to kMaxBlock poses of one mechanism at once, all with the same guide, into
/// prepared poses: each step of the scope runs for every pose before the next step. The poses
/// are independent, so their chains of square roots, divisions and library calls overlap in the
/// processor instead of each waiting on its own. The numbers are those solvePoseInto gives pose
/// by pose. Returns how many poses were solved, their reports in `reports`: all of them, or up
/// to and including the first that cannot be assembled. A sweep keeps nothing after that one,
/// so the poses after it are not solved further and what they hold means nothing. Mechanisms
/// without free points only (Newton starts each pose from the one before). Never throws or
/// allocates.
std::size_t solveBlockInto(const Mechanism& mechanism, std::span<const DriverState> drivers,
                           const SolveRequest& request, std::span<Pose* const> poses, const BranchGuide& guide,
                           const SolveScope& scope, std::span<PoseReport> reports);

/// Convenience: validates, solves with the mechanism's branches, and turns a failure into an
/// Error whose message names the point, the input angle and the reason.
Result<Pose> solvePose(const Mechanism& mechanism, const DriverState& driver, const SolveRequest& request = {});

/// A sentence explaining a failed report, e.g. "C cannot be assembled at crank angle 200°:
/// B and O4 are 125 mm apart, more than coupler + rocker = 115 mm".
std::string describeFailure(const Mechanism& mechanism, const PoseReport& report, const Pose& pose, double inputAngle);

}  // namespace linkwright::kinematics
