#pragma once
// A solved pose differentiated with respect to one dimension of the linkage, exactly: every
// point's position, velocity and acceleration and every link's angle, ω and α, each with its
// derivative with respect to the dimension, as jets (motion_jet.h). Derivation:
//
//   The pose solver places the points in order, each by a closed form of the points before it
//   and of its own numbers (pose_solver.h: a crank tip O + l(cos φ, sin φ); an RRR joint
//   C = P1 + a·u ± h·n with a = (l1² − l2² + L²)/(2L), h from Heron (rrr_dyad.h); a slider
//   s = −b ± √(l² − dist²) on its guide (rrp_dyad.h); a slotted link's tip O + l·r/|r|; two
//   guides' crossing; a point on a link base + along·e + across·e⊥). So each position is a
//   composite function x_i(q, p) of the input q and the numbers p, and the chain rule taken
//   point by point, in the solver's order, is the implicit-function derivative of the loop
//   equations Φ(x, q, p) = 0 (each point's two equations solved for that point alone):
//     ∂x_i/∂p = −(∂Φ_i/∂x_i)⁻¹ (∂Φ_i/∂p + Σ_{j<i} ∂Φ_i/∂x_j · ∂x_j/∂p).
//   Evaluating the closed forms in jet arithmetic with q(t) = q + q̇t + q̈t²/2 and p + δp does
//   exactly that, and also differentiates in t: ẋ and ẍ, the solver's velocity and
//   acceleration (which it gets from the differentiated loop equations, the same numbers up to
//   round-off), come with ∂ẋ/∂p and ∂ẍ/∂p. A link's angle θ = atan2(Δy, Δx) of its ends gives
//   ω = θ̇, α = θ̈ and their derivatives the same way.
//
//   Branches: each two-candidate point takes the candidate nearer the solver's position in
//   `nominal`, so the jets follow the branch the sweep tracked. Free points (Newton groups,
//   newton_group.h) solve Φ(x) = (|pa − pb|² − L²) = 0 for the group; in jet arithmetic the
//   iteration x ← x − J₀⁻¹Φ(x), J₀ the real Jacobian at the solver's positions, gains one
//   order of the series per step (the error is multiplied by a jet without constant term), so
//   four steps from the solver's positions make the series exact.
//
//   Toggles: at a dyad's toggle the derivatives do not exist (they grow without bound as it
//   nears); callers use them only where the sweep's report is Ok.

#include "kinematics/analysis/motion_jet.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

#include <span>
#include <vector>

namespace linkwright::kinematics {

/// A pose as jets: one entry per point and per link of the mechanism.
struct PoseJet {
  std::vector<JetVector> position;   ///< length unit; rates per s, per s²; ∂/∂p per unit of p
  std::vector<MotionJet> linkAngle;  ///< rad (not unwrapped); ω rad/s, α rad/s²
};

/// The pose of `mechanism` at `driver`, differentiated with respect to one dimension p.
/// `stepped` has the structure of `mechanism` (same points, links, constraints and kinds),
/// and each of its numbers differs from `mechanism`'s by that number's derivative with
/// respect to p (a unit step of p, when the numbers are affine in p). `nominal` holds the
/// solver's positions at `driver` (Pose::position, or a sweep's sample): the branches and
/// Newton's start. False (and `out` meaningless) if the structures differ or a point cannot
/// be placed; assumes checkMechanism passed.
bool differentiatePose(const Mechanism& mechanism, const Mechanism& stepped, const DriverState& driver,
                       std::span<const Eigen::Vector2d> nominal, PoseJet& out);

}  // namespace linkwright::kinematics
