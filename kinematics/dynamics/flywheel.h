#pragma once
// A flywheel on the crank shaft, sized by the energy equation and checked by forward dynamics.
// With a flywheel I_f and a motor giving the constant mean torque T̄ (crank_terms.h's terms):
//
//   Energy. d/dθ [½ (I_f + I_eq(θ)) θ̇²] = T̄ − T_s(θ), so the kinetic energy at θ is
//     K(θ) = K₀ + W(θ), W(θ) = ∫θ₀^θ (T̄ − T_s) dφ (the integral of T_s's series), and the
//   speed |θ̇| = √(2 K / (I_f + I_eq)), its slowest and fastest refined between samples on the
//   terms' series. K₀ is set (secant iterations) so that the mean speed (ω_max + ω_min)/2 is
//   the turn's ω; Cs = (ω_max − ω_min)/ω then follows from I_f. The flywheel for a wanted Cs is
//   found by iterating I_f ← (I_f + Ī)·Cs(I_f)/Cs − Ī (Ī the mean I_eq), which the textbook
//   formula I = ΔE/(Cs ω²) starts: that formula neglects the linkage's own inertia beside the
//   flywheel's, and is kept beside this one for comparison.
//   Motion. θ̈ = (T̄ − T_s(θ) − ½ I_eq'(θ) θ̇²) / (I_f + I_eq(θ)), integrated in time by the
//     classical Runge–Kutta method (four stages, four steps per sample interval, at most
//     kMostRunSteps), the terms their series between samples: an independent check of the
//     energy method, from the same starting speed.

#include "kinematics/dynamics/crank_terms.h"
#include "kinematics/model/result.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// One turn of the crank with a flywheel, as integrated in time.
struct FlywheelRun {
  std::vector<double> time;       ///< s, from 0
  std::vector<double> angle;      ///< rad, the crank's
  std::vector<double> speed;      ///< rad/s, the crank's
  double meanSpeed = 0.0;         ///< rad/s, (ω_max + ω_min)/2, signed as ω
  double speedFluctuation = 0.0;  ///< Cs = (ω_max − ω_min)/|mean speed|, as run
  double slowest() const;         ///< rad/s, the least |speed| of the run
  double fastest() const;         ///< rad/s, the largest |speed| of the run
};

/// The coefficients of speed fluctuation a flywheel is sized for: below 1e-5 the speed's
/// fluctuation is round-off of the speed itself, above 0.9 the mean speed means little.
inline constexpr double kMinSpeedFluctuation = 1e-5;
inline constexpr double kMaxSpeedFluctuation = 0.9;

/// Error naming "cs" unless kMinSpeedFluctuation ≤ `cs` ≤ kMaxSpeedFluctuation.
std::optional<Error> checkSpeedFluctuation(double cs);

/// The crank's speed over the turn with a flywheel, by the energy equation (rad/s, signed as ω).
struct FlywheelSpeeds {
  std::vector<double> speed;  ///< at each of the terms' samples
  double slowest = 0.0;       ///< the least |speed|, refined between samples
  double fastest = 0.0;       ///< the largest |speed|, refined between samples
  /// Cs = (ω_max − ω_min)/ω, ω = (ω_max + ω_min)/2
  double fluctuation() const { return (fastest - slowest) / (0.5 * (fastest + slowest)); }
};

/// The speed with a flywheel of `flywheelInertia` kg·m², by the energy equation, its mean speed
/// (ω_max + ω_min)/2 set to the turn's |ω|.
FlywheelSpeeds flywheelSpeeds(const CrankTerms& terms, double flywheelInertia);

/// The most time steps a forward-dynamics run takes over the turn.
inline constexpr std::size_t kMostRunSteps = 16384;

/// The flywheel inertia (kg·m², ≥ 0) that holds the speed within `cs` by the energy equation;
/// 0 when the linkage's own inertia already does. Error naming "cs" outside (0, 1), or when the
/// iteration does not converge.
Result<double> sizeFlywheel(const CrankTerms& terms, double cs);

/// Integrates one turn (forward dynamics) with a flywheel of `flywheelInertia` kg·m² (≥ 0,
/// finite; error naming "flywheel inertia" otherwise), starting at the terms' first angle at
/// the speed the energy equation gives there.
Result<FlywheelRun> runFlywheel(const CrankTerms& terms, double flywheelInertia);

}  // namespace linkwright::kinematics
