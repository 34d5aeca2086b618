#pragma once
// Closed-form RRP dyad: the joint C held at distance l from a known point P1 (pin) and sliding
// on a straight guide fixed to the ground, the line Q + s·u (u a unit vector). The slider-crank
// is a crank and one RRP dyad. Derivation (× the scalar cross):
//
//   Position. |Q + s·u − P1|² = l²  ⇒  s² + 2b·s + c = 0,  b = u·(Q − P1),  c = |Q − P1|² − l²,
//     s = −b ± √(b² − c)   (real iff the distance from P1 to the guide, |u×(P1 − Q)|, ≤ l).
//   Branch::Open takes +√ (C further along u), Crossed −√.
//
//   Velocity. With r = C − P1 and C moving along u only (vC = ṡ·u):
//     (C − P1)·(vC − v1) = 0  ⇒  ṡ = (r·v1) / (r·u).
//   Acceleration. Differentiating again, aC = s̈·u:
//     r·(aC − a1) + |vC − v1|² = 0  ⇒  s̈ = (r·a1 − |vC − v1|²) / (r·u).
//   r·u = 0 (the rod at right angles to the guide) is the toggle: the position exists, the
//   rates do not; flagged below the same |sin| threshold as the RRR dyad (kSingularSine).

#include "kinematics/solve/rrr_dyad.h"

#include <Eigen/Core>

namespace linkwright::kinematics {

/// Both candidate positions of C along the guide, or why there are none.
struct RrpCandidates {
  AssemblyFailure failure = AssemblyFailure::None;
  double open = 0.0;      ///< s for Branch::Open (+√), along u from Q
  double crossed = 0.0;   ///< s for Branch::Crossed (−√)
  double reachGap = 0.0;  ///< l − distance(P1, guide): ≥ 0 when it assembles; 0 at the toggle
};

/// Solves for s. `guideDirection` must be a unit vector; `length` positive.
RrpCandidates rrpCandidates(const Eigen::Vector2d& p1, double length, const Eigen::Vector2d& guidePoint,
                            const Eigen::Vector2d& guideDirection);

/// ṡ (or s̈) from r = C − P1 and the right-hand side r·v1 (or r·a1 − |vC − v1|²). Returns false
/// at the toggle, |r·u| ≤ kSingularSine·|r|, leaving `rate` untouched.
bool rrpSolveRate(const Eigen::Vector2d& r, const Eigen::Vector2d& guideDirection, double rhs, double& rate);

}  // namespace linkwright::kinematics
