#pragma once
// Closed-form RRR dyad: the joint C held at distance l1 from a known point P1 and at l2 from a
// known point P2 (both may move). Derivation (all vectors in the plane, × the scalar cross):
//
//   Position. |C−P1| = l1, |C−P2| = l2. With d = P2−P1, L = |d|, u = d/L, n = u rotated +90°:
//     C = P1 + a·u + s·h·n,   a = (l1² − l2² + L²) / (2L),
//     h = √((l1+l2−L)(l1+l2+L)(L−l1+l2)(L+l1−l2)) / (2L)      (Heron; stable near toggle)
//   and s = +1 for Branch::Open, −1 for Crossed, since (C−P1)×(C−P2) = s·h·L.
//   It assembles iff |l1−l2| ≤ L ≤ l1+l2 (within a relative tolerance, then h = 0).
//
//   Velocity. Differentiate (C−Pk)·(C−Pk) = lk²:  (C−Pk)·(vC − vk) = 0, k = 1, 2, so
//     [r1ᵀ; r2ᵀ] vC = [r1·v1; r2·v2],  rk = C − Pk,  det = r1×r2 = s·h·L.
//   Acceleration. Differentiate again: rk·(aC − ak) + |vC − vk|² = 0, so
//     [r1ᵀ; r2ᵀ] aC = [r1·a1 − |vC−v1|²; r2·a2 − |vC−v2|²]   (same matrix).
//   The matrix is singular when C, P1, P2 are collinear (h = 0, transmission angle 0° or
//   180°): the position exists, the rates do not. We flag that instead of dividing by ~0.

#include "kinematics/model/vec2.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

/// Why a dyad cannot be assembled.
enum class AssemblyFailure {
  None,
  TooFar,         ///< |P1P2| > l1 + l2: the two links cannot reach each other
  TooClose,       ///< |P1P2| < |l1 − l2|: one circle lies inside the other
  Coincident,     ///< P1 and P2 coincide: C is undetermined
  Parallel,       ///< two guides are parallel: their sliders' pin is undetermined
  NoConvergence,  ///< Newton did not close a group of free points (newton_group.h)
};

/// Relative tolerance on the assembly limits |l1−l2| ≤ L ≤ l1+l2: a pose past a limit by less
/// than this fraction of l1+l2 is taken as exactly at it (round-off, not a real gap).
inline constexpr double kAssemblyTolerance = 1e-10;
/// Below this |sin(transmission angle)| the dyad is treated as singular. Round-off in the
/// position (≈1e-16 relative) reaches the velocity divided by sin² and the acceleration,
/// which uses the velocity and divides once more, by sin³: at 1e-4 the acceleration is still
/// good to about 1e-4 relative; closer to the toggle it would be noise, so we flag it.
inline constexpr double kSingularSine = 1e-4;

/// Both candidate positions of C, or why there are none.
struct RrrCandidates {
  AssemblyFailure failure = AssemblyFailure::None;
  Eigen::Vector2d open = Eigen::Vector2d::Zero();     ///< s = +1
  Eigen::Vector2d crossed = Eigen::Vector2d::Zero();  ///< s = −1
  double halfSeparation = 0.0;                        ///< h: half the distance between the two candidates
  double distance = 0.0;                              ///< L = |P2 − P1|
};

/// Solves the dyad's position for both branches. Lengths positive, points finite.
inline RrrCandidates rrrCandidates(const Eigen::Vector2d& p1, double l1, const Eigen::Vector2d& p2, double l2) {
  RrrCandidates out;
  const Eigen::Vector2d d = p2 - p1;
  const double L = d.norm();
  out.distance = L;
  const double slack = kAssemblyTolerance * (l1 + l2);
  if (L <= slack) {
    out.failure = AssemblyFailure::Coincident;
    return out;
  }
  // Heron's factors: each is a distance to one assembly limit, computed without cancellation.
  double reach = l1 + l2 - L;            // ≥ 0 unless too far
  double inner = L - std::abs(l1 - l2);  // ≥ 0 unless too close
  if (reach < -slack) {
    out.failure = AssemblyFailure::TooFar;
    return out;
  }
  if (inner < -slack) {
    out.failure = AssemblyFailure::TooClose;
    return out;
  }
  const bool pastLimit = reach < 0.0 || inner < 0.0;
  reach = std::max(reach, 0.0);
  inner = std::max(inner, 0.0);
  // One division, made while the factors are multiplied, instead of three after them.
  const double inverse = 1.0 / L;
  const double h = 0.5 * std::sqrt(reach * (l1 + l2 + L) * inner * (L + std::abs(l1 - l2))) * inverse;
  double a = 0.5 * (l1 * l1 - l2 * l2 + L * L) * inverse;
  // Past a limit (within the slack) the circles do not meet, and the foot can lie beyond the
  // first circle: by slack·l2/L at the inner limit, without bound as the parents close in.
  // At ±l1 the first length holds exactly and the second misses by the gap, at most
  // kAssemblyTolerance·(l1 + l2).
  if (pastLimit) a = std::clamp(a, -l1, l1);
  const Eigen::Vector2d u = d * inverse;
  const Eigen::Vector2d n(-u.y(), u.x());
  const Eigen::Vector2d foot = p1 + a * u;
  out.open = foot + h * n;
  out.crossed = foot - h * n;
  out.halfSeparation = h;
  return out;
}

/// |sin| of the angle at C between C→P1 and C→P2 (0 at a toggle position).
double rrrSine(const Eigen::Vector2d& c, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2);

/// Solves the 2×2 system [r1ᵀ; r2ᵀ] x = rhs (see the derivation above). Returns false when
/// |r1×r2| ≤ kSingularSine·|r1|·|r2|, leaving x untouched.
bool rrrSolveRates(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, const Eigen::Vector2d& rhs,
                   Eigen::Vector2d& x);

/// 1 / (r1 × r2), the rate equations' determinant inverted once for velocity and acceleration,
/// into `inverse`; false (leaving it untouched) when |r1×r2| ≤ kSingularSine·scale, scale being
/// |r1|·|r2| (an RRR dyad knows it without square roots: l1·l2).
inline bool rrrInverseDeterminant(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, double scale, double& inverse) {
  const double det = cross(r1, r2);
  if (!(std::abs(det) > kSingularSine * scale)) return false;
  inverse = 1.0 / det;
  return true;
}

/// x with [r1ᵀ; r2ᵀ] x = rhs by Cramer's rule, given 1 / (r1 × r2).
inline Eigen::Vector2d rrrSolve(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, double inverseDeterminant,
                                const Eigen::Vector2d& rhs) {
  return {(rhs.x() * r2.y() - r1.y() * rhs.y()) * inverseDeterminant,
          (r1.x() * rhs.y() - rhs.x() * r2.x()) * inverseDeterminant};
}

}  // namespace linkwright::kinematics
