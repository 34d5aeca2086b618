#include "kinematics/dynamics/machine_duty.h"

#include "kinematics/dynamics/flywheel.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

// A mean that is round-off beside the turn's peak (a linkage without loads or gravity takes
// back all it is given) is 0, not 1e-17.
double roundOffToZero(double mean, double peak) { return std::abs(mean) <= 1e-12 * std::abs(peak) ? 0.0 : mean; }

MotorDuty motorDuty(const MachineDuty& d, const DutyOptions& o) {
  MotorDuty m;
  m.speed = o.gearRatio * d.omega;
  std::vector<double> torque(d.torque.size());
  for (std::size_t i = 0; i < torque.size(); ++i) {
    const double t = d.torque[i];
    torque[i] = t * d.omega > 0.0 ? t / (o.gearRatio * o.efficiency) : t * o.efficiency / o.gearRatio;
  }
  m.rmsTorque = std::sqrt(turnMean(d.angle, [&](std::size_t i) { return torque[i] * torque[i]; }));
  m.meanPower = turnMean(d.angle, [&](std::size_t i) { return torque[i] * m.speed; });
  for (const double t : torque) {
    m.peakTorque = std::max(m.peakTorque, std::abs(t));
    m.peakPower = std::max(m.peakPower, t * m.speed);
  }
  m.meanPower = roundOffToZero(m.meanPower, m.peakPower);
  if (!o.ratedTorque && !o.ratedSpeed) return m;
  const double rpm = std::abs(m.speed) * 60.0 / kTurn;
  if (o.ratedSpeed && std::abs(m.speed) > *o.ratedSpeed) {
    m.verdict = "too slow: the crank needs " + formatShort(rpm) + " rpm at the motor, rated " +
                formatShort(*o.ratedSpeed * 60.0 / kTurn) + " rpm";
  } else if (o.ratedTorque && m.rmsTorque > *o.ratedTorque) {
    m.verdict = "too weak: RMS torque " + formatShort(m.rmsTorque, 4) + " N·m at the motor exceeds the rated " +
                formatShort(*o.ratedTorque, 4) + " N·m";
  } else {
    m.verdict = "adequate";
    if (o.ratedTorque)
      m.verdict += ": RMS torque " + formatShort(m.rmsTorque, 4) + " N·m is " +
                   formatShort(100.0 * m.rmsTorque / *o.ratedTorque, 3) + " % of the rated " +
                   formatShort(*o.ratedTorque, 4) + " N·m, peak " + formatShort(m.peakTorque / *o.ratedTorque, 3) +
                   " times the rating";
    if (o.ratedSpeed)
      m.verdict += std::string(o.ratedTorque ? "; " : ": ") + formatShort(rpm) + " rpm of the rated " +
                   formatShort(*o.ratedSpeed * 60.0 / kTurn) + " rpm";
  }
  return m;
}

}  // namespace

std::optional<Error> checkDutyOptions(const DutyOptions& o) {
  if (o.speedFluctuation)
    if (auto e = checkSpeedFluctuation(*o.speedFluctuation)) return e;
  if (!(o.gearRatio >= 1.0 / kMaxGearRatio && o.gearRatio <= kMaxGearRatio))
    return invalid("gear ratio", "the gear ratio must be between 1e-6 and 1e6 motor turns per crank turn (got " +
                                     formatNumber(o.gearRatio) + ")");
  if (!(o.efficiency > 0.0 && o.efficiency <= 1.0))
    return invalid("efficiency",
                   "the gearbox efficiency must be above 0 and at most 1 (got " + formatNumber(o.efficiency) + ")");
  if (o.ratedTorque && !(*o.ratedTorque > 0.0 && *o.ratedTorque <= kMaxTorque))
    return invalid("rated torque",
                   "the rated torque must be positive and at most 1e33 N·m (got " + formatNumber(*o.ratedTorque) + ")");
  if (o.ratedSpeed && !(*o.ratedSpeed > 0.0 && *o.ratedSpeed <= kMaxOmega * kMaxGearRatio))
    return invalid("rated speed", "the rated speed must be positive and at most 1e12 rad/s (got " +
                                      formatNumber(*o.ratedSpeed) + " rad/s)");
  return std::nullopt;
}

Result<MachineDuty> machineDuty(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                                const DutyOptions& options) {
  if (auto e = checkCrankTurn(mechanism, turn)) return *e;
  if (auto e = checkDutyOptions(options)) return *e;
  const auto moving = turnForces(mechanism, dynamics, turn, turn.omega, 0.0);
  if (!moving) return moving.error();
  const ForceSweep* forces = &moving->forces;

  MachineDuty d;
  d.omega = turn.omega;
  d.torque = forces->driveTorque;
  d.angle.resize(turn.samples);
  for (std::size_t j = 0; j < turn.samples; ++j) d.angle[j] = sweepAngle(turn, j);
  if (d.angle.back() < d.angle.front()) {  // a grid run backwards: integrate over increasing θ
    std::reverse(d.angle.begin(), d.angle.end());
    std::reverse(d.torque.begin(), d.torque.end());
  }
  d.meanTorque = turnMean(d.angle, [&](std::size_t i) { return d.torque[i]; });
  d.rmsTorque = std::sqrt(turnMean(d.angle, [&](std::size_t i) { return d.torque[i] * d.torque[i]; }));
  d.peakPower = -kMaxTorque * kMaxOmega;
  for (const double t : d.torque) {
    d.peakTorque = std::max(d.peakTorque, std::abs(t));
    d.peakPower = std::max(d.peakPower, t * d.omega);
  }
  d.meanTorque = roundOffToZero(d.meanTorque, d.peakTorque);
  d.meanPower = d.meanTorque * d.omega;
  d.energy.assign(d.angle.size(), 0.0);
  for (std::size_t i = 1; i < d.angle.size(); ++i)
    d.energy[i] = d.energy[i - 1] + 0.5 * ((d.meanTorque - d.torque[i - 1]) + (d.meanTorque - d.torque[i])) *
                                        (d.angle[i] - d.angle[i - 1]);
  const auto [low, high] = std::minmax_element(d.energy.begin(), d.energy.end());
  d.energyFluctuation = *high - *low;
  if (options.speedFluctuation) {
    d.textbookFlywheelInertia = d.energyFluctuation / (*options.speedFluctuation * d.omega * d.omega);
    const auto terms = crankTerms(mechanism, dynamics, turn, moving->forces);
    if (!terms) return terms.error();
    const auto flywheel = sizeFlywheel(*terms, *options.speedFluctuation);
    if (!flywheel) return flywheel.error();
    d.flywheelInertia = *flywheel;
    auto run = runFlywheel(*terms, *flywheel);
    if (!run) return run.error();
    d.flywheelRun = std::move(run).value();
  }
  for (std::size_t j = 0; j < forces->size(); ++j) {
    d.virtualWorkDifference =
        std::max(d.virtualWorkDifference, std::abs(forces->virtualWorkTorque[j] - forces->driveTorque[j]));
    d.shakingForcePeak = std::max(d.shakingForcePeak, forces->shakingForce[j].norm());
    d.shakingMomentPeak = std::max(d.shakingMomentPeak, std::abs(forces->shakingMoment[j]));
    for (const auto& joint : forces->revolute) d.bearingLoadPeak = std::max(d.bearingLoadPeak, joint[j].norm());
  }
  d.motor = motorDuty(d, options);
  return d;
}

}  // namespace linkwright::kinematics
