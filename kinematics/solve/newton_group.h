#pragma once
// Newton–Raphson for a group of free points (FreePoint in mechanism.h): a run of consecutive
// free points solved together from the distance constraints that close on them, for loops
// that no order of dyads solves (a triad: Stephenson III driven from the wrong link,
// Stephenson II). Everything before the group is already solved; the pose solver calls this
// when it reaches the group's first point. Derivation (× the scalar cross, · the dot):
//
//   Unknowns q = (p1, …, pk) ∈ R^2k, the group's points; its constraints are those whose later
//   point lies in it, exactly 2k of them (checkMechanism), each (a, b, L) written as
//     Φ(q) = (|pa − pb|² − L²) / (2L)      (= |pa − pb| − L to first order at closure).
//   The squared form is a polynomial: smooth even where pa = pb, no square root. Dividing by
//   2L makes each point's part of a row of J a unit vector at closure and the residual a
//   length, so one tolerance relative to the linkage's size means the same for a short link
//   and a long one.
//
//   Jacobian. With d = pa − pb: ∂Φ/∂pa = dᵀ/L, ∂Φ/∂pb = −dᵀ/L. J holds the columns of the
//   group's points; the columns of solved points (J_k) move to the right-hand side.
//   Position. Newton: J(q) Δq = −Φ(q), q ← q + tΔq until max|Φ| ≤ tolerance × size. t = 1
//   unless that step is longer than the linkage's size (then shortened to it) or does not
//   reduce |Φ|² by the Armijo fraction (then halved, at most kNewtonHalvings times; if none
//   helps, |Φ| sits at a local minimum above zero: the loop cannot close, we report it).
//   Velocity. dΦ/dt = d·(va − vb)/L = 0, so J q̇ = −J_k q̇_k: row (a, b) has right-hand side
//     −d·va/L if a is solved, +d·vb/L if b is solved (0 for a point of the group).
//   Acceleration. d²Φ/dt² = [d·(aa − ab) + |va − vb|²]/L = 0, so J q̈ = −J_k q̈_k − J̇ q̇, the
//     J̇ q̇ term being |va − vb|²/L per row, with the velocities just found.
//   Both use one LU factorization (partial pivoting) of J at the converged q. J is singular
//   where the group can move with the input held (a triad's three binaries concurrent, a
//   converted dyad at its toggle): when LU's estimate of J's reciprocal condition number
//   (‖J‖₁‖J⁻¹‖₁)⁻¹ is below kSingularSine, the positions stand and the rates are undefined
//   (small_lu.h: where a cheap bound already puts it above, the estimate is not run).
//   For a converted RRR dyad J = [u1ᵀ; u2ᵀ] (unit rows), whose estimate lies between
//   |sin γ|/(2√2) and |sin γ| (γ the transmission angle): the closed form's test, within 3×.
//
//   Start: the pose solver's choice (pose_solver.cpp): the guide's prediction, else the pose's
//   positions if Pose::assembled (in a sweep, the free points' path extrapolated from the last
//   three samples, so that one step usually meets the tolerance: sweep.cpp), else the
//   guesses; a warm start that fails is retried once from the guesses.
//   Workspace: each group size 2k (k ≤ kMaxFreeGroupPoints, constraint_form.h) has its own
//   fixed-size vectors and LU (small_lu.h) on the stack, so a solve never allocates, its loops
//   have constant bounds, the solver keeps no state, and Pose stays a plain value.

#include "kinematics/model/constraint_form.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <cstddef>
#include <optional>

namespace linkwright::kinematics {

/// Backtracking halvings of a Newton step before Newton gives up (a step cut to 1/1024).
inline constexpr int kNewtonHalvings = 10;

enum class NewtonStatus {
  Converged,      ///< positions, and the rates requested
  Singular,       ///< positions converged, J is singular there: rates not written
  NoConvergence,  ///< the iteration cap was reached or |Φ| stopped decreasing
};

/// How one group's solve went.
struct NewtonOutcome {
  NewtonStatus status = NewtonStatus::Converged;
  int iterations = 0;     ///< Newton steps taken (0 if the start already met the tolerance)
  double residual = 0.0;  ///< max |Φ| at the end, length unit
  bool operator==(const NewtonOutcome&) const = default;
};

/// Solves the free points [first, last) (a whole group, see freeGroupEnd) starting from their
/// positions in `pose`, every earlier point being solved (and its rates, if asked for). Writes
/// their positions, then, if asked and J is regular, velocities and accelerations. On
/// NoConvergence the positions hold Newton's last iterate. Never allocates or throws;
/// assumes checkMechanism passed.
NewtonOutcome solveFreeGroup(const Mechanism& mechanism, std::size_t first, std::size_t last,
                             const NewtonSettings& settings, bool velocities, bool accelerations, Pose& pose);

/// |pa − pb| − L at the pose's positions (length unit): how far a constraint is from closing.
double constraintMisfit(const DistanceConstraint& constraint, const Pose& pose);

/// Error naming "newton.tolerance" or "newton.maxIterations" unless 1e-15 ≤ tolerance < 1
/// and 1 ≤ maxIterations ≤ 1000.
std::optional<Error> checkNewtonSettings(const NewtonSettings& settings);

}  // namespace linkwright::kinematics
