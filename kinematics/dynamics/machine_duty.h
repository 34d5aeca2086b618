#pragma once
// From motion to machine: what one turn of a crank asks of its motor, a flywheel and the frame
// (Norton, Design of Machinery, ch. 11 and 12; Shigley and Uicker, Theory of Machines and
// Mechanisms, ch. 16). The driving torque T(θ) is inverse dynamics' (inverse_dynamics.h) over
// one full turn at the constant speed ω; SI throughout.
//
//   Crank. Mean T̄ = (1/2π)∮T dθ, RMS = √((1/2π)∮T² dθ), peak = max |T|; power P = T ω (W),
//     mean P̄ = T̄ ω, peak = max P (the motor's largest demand).
//   Flywheel. A motor giving T̄ steadily leaves the surplus E(θ) = ∫θ₀^θ (T̄ − T) dφ to the
//     rotating parts; the energy fluctuation is ΔE = max E − min E (J). A flywheel of inertia I
//     on the crank shaft then holds the speed between ω_min and ω_max with
//     ΔE = ½ I (ω_max² − ω_min²) = I ω² Cs, Cs = (ω_max − ω_min)/ω, ω = (ω_max + ω_min)/2, so
//     I = ΔE / (Cs ω²), the textbook flywheel. It neglects the linkage's own inertia beside the
//     flywheel's; flywheel.h sizes it with both by the energy equation, which is what Linkwright
//     gives as the flywheel, and checks that by forward dynamics (the run is returned).
//   Exactness. Every figure is read off the series of the turn's samples (periodic_series.h):
//     means by the trapezoidal rule on the periodic grid, E(θ) by the series' integral, the
//     peaks and E's extremes refined between samples, the motor's figures split where the
//     torque changes sign. For a linkage that turns smoothly they converge faster than any power
//     of the sample count. Each figure's error is estimated by the same figure read off every
//     other sample (an upper estimate), relative to its scale (the peak torque for the torques,
//     the peak power for the powers, the figure itself otherwise): `accuracy`.
//   Motor and gearbox, ratio N (motor turns per crank turn) and efficiency η: the motor turns at
//     N ω; where it drives (T ω > 0) it gives T/(N η), where the linkage drives it back T η/N.
//   Check. The driving torque by virtual work beside the Newton–Euler one at every sample; the
//   largest difference is reported (it must be round-off).
//   A mean within 1e-12 of the turn's peak is round-off and given as 0 (a linkage without loads
//   or gravity takes back over the turn all it is given).
//   Frame. The peak shaking force max |F_s| and moment max |M_s| (about the crank's pivot); and
//   the largest force through any pin joint, the bearing load a balance trades against.

#include "kinematics/dynamics/crank_terms.h"
#include "kinematics/dynamics/flywheel.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// Largest accepted gearbox ratio, either way (motor turns per crank turn).
inline constexpr double kMaxGearRatio = 1e6;
/// Least accepted gearbox efficiency: below it the motor's torques stop being physical.
inline constexpr double kMinEfficiency = 0.01;
/// Largest accepted motor rating: torque (N·m) and speed (rpm).
inline constexpr double kMaxRatedTorque = 1e9;
inline constexpr double kMaxRatedRpm = 1e7;

/// What the user asks of a turn besides the torque itself.
struct DutyOptions {
  std::optional<double> speedFluctuation;  ///< Cs, (ω_max − ω_min)/ω, in (0, 1): sizes a flywheel
  double gearRatio = 1.0;                  ///< N, motor turns per crank turn, in [1e-6, 1e6]
  double efficiency = 1.0;                 ///< η of the gearbox, in [kMinEfficiency, 1]
  std::optional<double> ratedTorque;       ///< N·m, the motor's continuous torque, in (0, kMaxRatedTorque]
  std::optional<double> ratedSpeed;        ///< rad/s, the motor's rated speed, in (0, kMaxRatedRpm rpm]
};

/// A torque over the turn through the gearbox, at the motor.
struct MotorDuty {
  double speed = 0.0;       ///< rad/s, N ω
  double rmsTorque = 0.0;   ///< N·m
  double peakTorque = 0.0;  ///< N·m, max |T_motor|
  double meanPower = 0.0;   ///< W, the motor's mean output
  double peakPower = 0.0;   ///< W
  std::string verdict;      ///< one line against the rated torque and speed; empty without them
};

/// What a turn asks of the machine.
struct MachineDuty {
  double omega = 0.0;              ///< rad/s, the crank's speed
  std::vector<double> angle;       ///< rad, the turn's samples
  std::vector<double> torque;      ///< N·m, T at each sample (the driving torque, CCW +)
  std::vector<double> energy;      ///< J, E(θ) = ∫(T̄ − T) dθ from the first sample
  double meanTorque = 0.0;         ///< N·m
  double rmsTorque = 0.0;          ///< N·m
  double peakTorque = 0.0;         ///< N·m, max |T|
  double meanPower = 0.0;          ///< W
  double peakPower = 0.0;          ///< W, max T ω
  double energyFluctuation = 0.0;  ///< J, ΔE
  /// kg·m² on the crank shaft that holds the speed within Cs (given), the linkage's own
  /// inertia counted (flywheel.h)
  std::optional<double> flywheelInertia;
  std::optional<double> textbookFlywheelInertia;  ///< kg·m², ΔE/(Cs ω²), with Cs given
  /// One turn with that flywheel and the mean torque, integrated in time (flywheel.h): the
  /// check that the speed varies by Cs; with Cs given
  std::optional<FlywheelRun> flywheelRun;
  double shakingForcePeak = 0.0;   ///< N
  double shakingMomentPeak = 0.0;  ///< N·m
  /// N·m, the largest |T by virtual work − T by Newton–Euler| over the turn (virtual_work.h):
  /// round-off when both are right
  double virtualWorkDifference = 0.0;
  double bearingLoadPeak = 0.0;  ///< N, the largest force through any pin joint
  MotorDuty motor;
  /// Each figure's relative error estimate (above) by its key in dutyFigures ("motor.…" for the
  /// motor's), 0 where the two readings agree to the bit; empty on an odd number of intervals,
  /// where there is no every other sample.
  std::map<std::string, double> accuracy;
  /// The largest of `accuracy` (0 when empty).
  double worstAccuracy() const;
};

/// One figure of a duty as every front end shows it: its key (the JSON's), its label, unit and
/// value, its relative error estimate, and the group it is listed under ("" or "motor").
struct DutyFigure {
  std::string key;    ///< "energy_fluctuation_J"
  std::string label;  ///< "energy fluctuation ΔE"
  std::string unit;   ///< "J"
  double value = 0.0;
  std::optional<double> accuracy;  ///< relative error estimate; none on an odd number of intervals
  std::string group;               ///< "" or "motor"
};

/// The duty's figures in the order they are listed (the flywheel's with Cs given).
std::vector<DutyFigure> dutyFigures(const MachineDuty& duty, const DutyOptions& options);

/// Error naming the field unless `options` are in their ranges (above).
std::optional<Error> checkDutyOptions(const DutyOptions& options);

/// The duty of one turn on its samples (checkCrankTurn, checkDutyOptions, then turnForces at
/// the turn's ω); an even number of sample intervals lets `accuracy` compare every other sample.
/// `cancel`, if given and set, stops it with ErrorCode::Cancelled.
Result<MachineDuty> machineDuty(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                                const DutyOptions& options, const std::atomic<bool>* cancel = nullptr);

}  // namespace linkwright::kinematics
