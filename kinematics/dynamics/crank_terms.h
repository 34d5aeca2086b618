#pragma once
// The crank's equation of motion over one turn, from inverse dynamics. A linkage driven by a
// crank has one degree of freedom, so the torque it needs at the crank is
//   T(θ, θ̇, θ̈) = T_s(θ) + I_eq(θ) θ̈ + ½ I_eq'(θ) θ̇²
// (Lagrange: its kinetic energy is ½ I_eq(θ) θ̇²). Inverse dynamics (inverse_dynamics.h) gives
// each term exactly at every sample of a turn, from three force sweeps: T_s, the static torque
// (loads and gravity), with the crank at rest (ω = 0, α = 0); I_eq = T(0, α = 1) − T_s; and
// ½ I_eq' = (T(ω, 0) − T_s)/ω² from the turn at its own speed ω. The flywheel (flywheel.h) is
// sized and run with them.

#include "kinematics/analysis/periodic_series.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// The most samples a turn may have: its duty holds the whole turn (three force sweeps) in
/// memory, about 2 kB a sample for a four-bar; 100000 is a sample every 0.0036°.
inline constexpr std::size_t kMaxTurnSamples = 100'000;

/// Error naming "driver" unless `mechanism` is driven by a crank.
std::optional<Error> checkCrankDriven(const Mechanism& mechanism);

/// Error unless `mechanism` is driven by a crank (checkCrankDriven) and `turn` is one full turn at a constant
/// ω ≠ 0 (fromAngle to fromAngle ± 2π, α = 0, no time base, 4 to kMaxTurnSamples samples).
std::optional<Error> checkCrankTurn(const Mechanism& mechanism, const SweepSpec& turn);

/// A turn's kinematics and the forces solved on them.
struct TurnSweep {
  SweepResult kinematics;
  ForceSweep forces;
};

/// The forces at every sample of `turn` with the crank at `omega` and `alpha` instead of the
/// turn's own: every sample must solve (Ok), else an error naming the first angle that does
/// not (a linkage that cannot turn fully, or a toggle where the forces are not determined).
/// `cancel`, if given and set, stops it with ErrorCode::Cancelled.
Result<TurnSweep> turnForces(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                             double omega, double alpha, const std::atomic<bool>* cancel = nullptr);

/// ∮ f dθ over a turn's samples `angle` by the trapezoidal rule; the last sample closes the
/// turn, which may run either way (the weights are |Δθ|). `f(i)` is the integrand at sample i.
template <typename F>
double turnIntegral(const std::vector<double>& angle, F f) {
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < angle.size(); ++i) {
    const double step = angle[i + 1] - angle[i];
    sum += 0.5 * (f(i) + f(i + 1)) * (step < 0.0 ? -step : step);
  }
  return sum;
}

/// The mean of f over the turn: turnIntegral over the turn's span.
template <typename F>
double turnMean(const std::vector<double>& angle, F f) {
  const double span = angle.back() - angle.front();
  return turnIntegral(angle, f) / (span < 0.0 ? -span : span);
}

/// The three terms at the turn's samples, ordered by increasing angle (a turn run backwards is
/// reversed), and the torque at the turn's speed they add up to; between samples each term is
/// its series (periodic_series.h), exact to round-off for a linkage that turns smoothly.
struct CrankTerms {
  double omega = 0.0;                ///< rad/s, the turn's speed
  std::vector<double> angle;         ///< rad, increasing; the last is the first + 2π
  std::vector<double> torque;        ///< N·m, T(θ, ω, 0)
  std::vector<double> staticTorque;  ///< N·m, T_s
  std::vector<double> inertia;       ///< kg·m², I_eq
  std::vector<double> halfSlope;     ///< kg·m²/rad, ½ I_eq'
  /// The series of T_s, I_eq and ½ I_eq' through the samples (the closing one left out).
  PeriodicSeries staticSeries() const;
  PeriodicSeries inertiaSeries() const;
  PeriodicSeries halfSlopeSeries() const;
  /// The terms at every other sample: the same figures read off them estimate the error.
  CrankTerms everyOther() const;
};

/// The terms of `turn` (checkCrankTurn), given its forces at its own speed (`moving`, from
/// turnForces(…, turn.omega, 0)); solves the two others.
Result<CrankTerms> crankTerms(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                              const ForceSweep& moving, const std::atomic<bool>* cancel = nullptr);

}  // namespace linkwright::kinematics
