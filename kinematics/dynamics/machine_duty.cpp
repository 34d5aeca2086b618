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

// What the figures are read from: one turn's samples in increasing θ, the closing one left out.
struct TurnSamples {
  double theta0 = 0.0;
  double omega = 0.0;
  std::vector<double> torque, shakeX, shakeY, moment;
  std::vector<std::vector<double>> jointX, jointY;
  std::optional<CrankTerms> terms;  // with Cs given

  TurnSamples everyOther() const {
    const auto pick = [](const std::vector<double>& v) {
      std::vector<double> half;
      for (std::size_t j = 0; j < v.size(); j += 2) half.push_back(v[j]);
      return half;
    };
    TurnSamples h{theta0, omega, pick(torque), pick(shakeX), pick(shakeY), pick(moment), {}, {}, std::nullopt};
    for (std::size_t i = 0; i < jointX.size(); ++i) {
      h.jointX.push_back(pick(jointX[i]));
      h.jointY.push_back(pick(jointY[i]));
    }
    if (terms) h.terms = terms->everyOther();
    return h;
  }
};

// The largest |F| of a vector known by its components' samples, refined between them.
double peakNorm(double theta0, const std::vector<double>& x, const std::vector<double>& y) {
  const PeriodicSeries sx(theta0, x), sy(theta0, y);
  std::vector<double> norms(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) norms[j] = std::hypot(x[j], y[j]);
  return refinePeriodicMaximum([&](double t) { return std::hypot(sx.value(t), sy.value(t)); }, theta0, norms).value;
}

// The mean over the turn of `integrand` (× the share of the turn) where `sign` is positive
// (negative with `positive` false): its series' integral between the zeros of sign's series,
// each found by bisection between the samples that bracket it.
double partMean(const PeriodicSeries& sign, const PeriodicSeries& integrand, bool positive) {
  const std::size_t n = sign.size();
  const double step = kTurn / static_cast<double>(n);
  std::vector<double> zeros;
  for (std::size_t j = 0; j < n; ++j) {
    const double a = sign.samples()[j], b = sign.samples()[(j + 1) % n];
    if ((a < 0.0) == (b < 0.0)) continue;
    double low = sign.sampleAngle(j), high = low + step;
    for (int i = 0; i < 60 && high - low > 1e-15; ++i) {
      const double mid = 0.5 * (low + high);
      ((sign.value(mid) < 0.0) == (a < 0.0) ? low : high) = mid;
    }
    zeros.push_back(0.5 * (low + high));
  }
  const auto wanted = [&](double theta) { return (sign.value(theta) > 0.0) == positive; };
  if (zeros.empty()) return wanted(sign.theta0()) ? integrand.mean() : 0.0;
  const PeriodicSeries anti = integrand.surplusSeries();
  const auto integral = [&](double theta) { return integrand.mean() * (theta - sign.theta0()) + anti.value(theta); };
  double sum = 0.0;
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    const double from = zeros[i], to = i + 1 < zeros.size() ? zeros[i + 1] : zeros.front() + kTurn;
    if (wanted(0.5 * (from + to))) sum += integral(to) - integral(from);
  }
  return sum / kTurn;
}

MotorDuty motorDuty(const MachineDuty& d, const PeriodicSeries& torque, const DutyOptions& o, double highest,
                    double lowest) {
  MotorDuty m;
  const double n = o.gearRatio, eta = o.efficiency;
  m.speed = n * d.omega;
  // Where the motor drives (T ω > 0) it gives T/(N η); where the linkage drives it, T η/N.
  const bool forward = d.omega > 0.0;
  std::vector<double> squares(torque.size());
  for (std::size_t j = 0; j < squares.size(); ++j) squares[j] = torque.samples()[j] * torque.samples()[j];
  const PeriodicSeries square(torque.theta0(), std::move(squares));
  const double drivingSquare = partMean(torque, square, forward);
  const double drivenSquare = square.mean() - drivingSquare;
  m.rmsTorque = std::sqrt(std::max(0.0, drivingSquare / (n * eta * n * eta) + drivenSquare * eta * eta / (n * n)));
  const double driving = partMean(torque, torque, forward), driven = torque.mean() - driving;
  const double drivingPeak = std::max(0.0, forward ? highest : -lowest);
  const double drivenPeak = std::max(0.0, forward ? -lowest : highest);
  m.peakTorque = std::max(drivingPeak / (n * eta), drivenPeak * eta / n);
  m.meanPower = d.omega * (driving / eta + driven * eta);
  const double absOmega = std::abs(d.omega);
  m.peakPower = drivingPeak > 0.0 ? drivingPeak * absOmega / eta : -drivenPeak * absOmega * eta;
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

// The figures of `d` read off `s` (its curves are left as they are).
std::optional<Error> readFigures(const TurnSamples& s, const DutyOptions& o, MachineDuty& d) {
  d.omega = s.omega;
  const PeriodicSeries torque(s.theta0, s.torque);
  const double highest = torque.maximum().value, lowest = torque.minimum().value;
  d.peakTorque = std::max(std::abs(highest), std::abs(lowest));
  d.meanTorque = roundOffToZero(torque.mean(), d.peakTorque);
  double square = 0.0;
  for (const double t : s.torque) square += t * t;
  d.rmsTorque = std::sqrt(square / static_cast<double>(s.torque.size()));
  d.meanPower = d.meanTorque * d.omega;
  d.peakPower = d.omega > 0.0 ? highest * d.omega : lowest * d.omega;
  // E(θ) = ∫(T̄ − T) dθ is minus the series' surplus integral.
  const PeriodicSeries surplus = torque.surplusSeries();
  d.energyFluctuation = surplus.maximum().value - surplus.minimum().value;
  d.shakingForcePeak = peakNorm(s.theta0, s.shakeX, s.shakeY);
  const PeriodicSeries moment(s.theta0, s.moment);
  d.shakingMomentPeak = std::max(std::abs(moment.maximum().value), std::abs(moment.minimum().value));
  d.bearingLoadPeak = 0.0;
  for (std::size_t i = 0; i < s.jointX.size(); ++i)
    d.bearingLoadPeak = std::max(d.bearingLoadPeak, peakNorm(s.theta0, s.jointX[i], s.jointY[i]));
  d.motor = motorDuty(d, torque, o, highest, lowest);
  if (o.speedFluctuation && s.terms) {
    d.textbookFlywheelInertia = d.energyFluctuation / (*o.speedFluctuation * d.omega * d.omega);
    const auto flywheel = sizeFlywheel(*s.terms, *o.speedFluctuation);
    if (!flywheel) return flywheel.error();
    d.flywheelInertia = *flywheel;
  }
  return std::nullopt;
}

// The scale a figure's error is measured against: the peak torque for a mean torque, the peak
// power for a mean power (both may be 0), the figure itself otherwise.
double scaleOf(const DutyFigure& f, const MachineDuty& d) {
  if (f.group == "motor" && f.key == "mean_power_W") return d.motor.peakTorque * std::abs(d.motor.speed);
  if (f.key == "mean_torque_Nm") return d.peakTorque;
  if (f.key == "mean_power_W") return d.peakTorque * std::abs(d.omega);
  // A balanced linkage's shaking force is zero to round-off: measured against its own size no
  // grid converges (a balanced four-bar ran to the largest grid and said "not converged"), so
  // against the forces in its bearings, and its moment against the driving torque.
  if (f.key == "shaking_force_peak_N") return std::max(std::abs(f.value), d.bearingLoadPeak);
  if (f.key == "shaking_moment_peak_Nm") return std::max(std::abs(f.value), d.peakTorque);
  return std::abs(f.value);
}

}  // namespace

double MachineDuty::worstAccuracy() const {
  double worst = 0.0;
  for (const auto& [key, bound] : accuracy) worst = std::max(worst, bound);
  return worst;
}

std::vector<DutyFigure> dutyFigures(const MachineDuty& d, const DutyOptions& o) {
  std::vector<DutyFigure> f{
      {"mean_torque_Nm", "driving torque, mean", "N·m", d.meanTorque, {}, ""},
      {"rms_torque_Nm", "driving torque, RMS", "N·m", d.rmsTorque, {}, ""},
      {"peak_torque_Nm", "driving torque, peak |T|", "N·m", d.peakTorque, {}, ""},
      {"mean_power_W", "power at the crank, mean", "W", d.meanPower, {}, ""},
      {"peak_power_W", "power at the crank, peak", "W", d.peakPower, {}, ""},
      {"energy_fluctuation_J", "energy fluctuation ΔE", "J", d.energyFluctuation, {}, ""},
  };
  if (d.flywheelInertia && d.textbookFlywheelInertia) {
    f.push_back({"flywheel_inertia_kg_m2",
                 "flywheel for Cs " + formatShort(o.speedFluctuation.value_or(0.0)),
                 "kg·m²",
                 *d.flywheelInertia,
                 {},
                 ""});
    f.push_back({"textbook_flywheel_inertia_kg_m2",
                 "textbook flywheel ΔE/(Cs ω²)",
                 "kg·m²",
                 *d.textbookFlywheelInertia,
                 {},
                 ""});
  }
  f.push_back({"shaking_force_peak_N", "shaking force, peak", "N", d.shakingForcePeak, {}, ""});
  f.push_back(
      {"shaking_moment_peak_Nm", "shaking moment about the crank's pivot, peak", "N·m", d.shakingMomentPeak, {}, ""});
  f.push_back({"bearing_load_peak_N", "bearing load, peak", "N", d.bearingLoadPeak, {}, ""});
  f.push_back({"rms_torque_Nm", "motor torque, RMS", "N·m", d.motor.rmsTorque, {}, "motor"});
  f.push_back({"peak_torque_Nm", "motor torque, peak", "N·m", d.motor.peakTorque, {}, "motor"});
  f.push_back({"mean_power_W", "motor power, mean", "W", d.motor.meanPower, {}, "motor"});
  f.push_back({"peak_power_W", "motor power, peak", "W", d.motor.peakPower, {}, "motor"});
  for (DutyFigure& figure : f) {
    const auto found = d.accuracy.find(figure.group.empty() ? figure.key : figure.group + "." + figure.key);
    if (found != d.accuracy.end()) figure.accuracy = found->second;
  }
  return f;
}

std::optional<Error> checkDutyOptions(const DutyOptions& o) {
  if (o.speedFluctuation)
    if (auto e = checkSpeedFluctuation(*o.speedFluctuation)) return e;
  if (!(o.gearRatio >= 1.0 / kMaxGearRatio && o.gearRatio <= kMaxGearRatio))
    return invalid("gear_ratio", "the gear ratio must be from 1e-6 to 1e6 motor turns per crank turn (got " +
                                     formatNumber(o.gearRatio) + ")");
  if (!(o.efficiency >= kMinEfficiency && o.efficiency <= 1.0))
    return invalid("efficiency",
                   "the gearbox efficiency must be from 0.01 to 1 (got " + formatNumber(o.efficiency) + ")");
  if (o.ratedTorque && !(*o.ratedTorque > 0.0 && *o.ratedTorque <= kMaxRatedTorque))
    return invalid("rated_torque", "the rated torque must be above 0 and at most 1e9 N·m (got " +
                                       formatNumber(*o.ratedTorque) + " N·m)");
  if (o.ratedSpeed && !(*o.ratedSpeed > 0.0 && *o.ratedSpeed <= rpmToRadPerSec(kMaxRatedRpm)))
    return invalid("rated_speed", "the rated speed must be above 0 and at most 1e7 rpm (got " +
                                      formatNumber(radPerSecToRpm(*o.ratedSpeed)) + " rpm)");
  return std::nullopt;
}

Result<MachineDuty> machineDuty(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& turn,
                                const DutyOptions& options, const std::atomic<bool>* cancel) {
  if (auto e = checkCrankTurn(mechanism, turn)) return *e;
  if (auto e = checkDutyOptions(options)) return *e;
  const auto moving = turnForces(mechanism, dynamics, turn, turn.omega, 0.0, cancel);
  if (!moving) return moving.error();
  const ForceSweep& forces = moving->forces;

  MachineDuty d;
  d.omega = turn.omega;
  d.torque = forces.driveTorque;
  d.angle.resize(turn.samples);
  for (std::size_t j = 0; j < turn.samples; ++j) d.angle[j] = sweepAngle(turn, j);
  TurnSamples s;
  s.omega = turn.omega;
  s.torque = forces.driveTorque;
  for (std::size_t j = 0; j < forces.size(); ++j) {
    s.shakeX.push_back(forces.shakingForce[j].x());
    s.shakeY.push_back(forces.shakingForce[j].y());
    s.moment.push_back(forces.shakingMoment[j]);
    d.virtualWorkDifference =
        std::max(d.virtualWorkDifference, std::abs(forces.virtualWorkTorque[j] - forces.driveTorque[j]));
  }
  for (const auto& joint : forces.revolute) {
    s.jointX.emplace_back();
    s.jointY.emplace_back();
    for (const Eigen::Vector2d& f : joint) {
      s.jointX.back().push_back(f.x());
      s.jointY.back().push_back(f.y());
    }
  }
  const bool backwards = d.angle.back() < d.angle.front();  // a grid run backwards: read over increasing θ
  std::vector<std::vector<double>*> columns{&d.angle, &d.torque, &s.torque, &s.shakeX, &s.shakeY, &s.moment};
  for (auto& c : s.jointX) columns.push_back(&c);
  for (auto& c : s.jointY) columns.push_back(&c);
  for (std::vector<double>* c : columns) {
    if (backwards) std::reverse(c->begin(), c->end());
    if (c != &d.angle && c != &d.torque) c->pop_back();  // the closing sample is the first again
  }
  s.theta0 = d.angle.front();
  if (options.speedFluctuation) {
    auto terms = crankTerms(mechanism, dynamics, turn, forces, cancel);
    if (!terms) return terms.error();
    s.terms = std::move(terms).value();
  }
  if (auto e = readFigures(s, options, d)) return *e;
  const PeriodicSeries surplus = PeriodicSeries(s.theta0, s.torque).surplusSeries();
  d.energy.resize(d.angle.size());
  for (std::size_t j = 0; j + 1 < d.energy.size(); ++j) d.energy[j] = -surplus.samples()[j];
  d.energy.back() = d.energy.front();
  if (s.terms && d.flywheelInertia) {
    auto run = runFlywheel(*s.terms, *d.flywheelInertia);
    if (!run) return run.error();
    d.flywheelRun = std::move(run).value();
  }
  // Each figure against the same figure read off every other sample.
  if (s.torque.size() >= 4 && s.torque.size() % 2 == 0) {
    MachineDuty half = d;
    if (auto e = readFigures(s.everyOther(), options, half)) return *e;
    const std::vector<DutyFigure> full = dutyFigures(d, options), coarse = dutyFigures(half, options);
    for (std::size_t i = 0; i < full.size(); ++i) {
      const double scale = scaleOf(full[i], d);
      const double difference = std::abs(full[i].value - coarse[i].value);
      d.accuracy[full[i].group.empty() ? full[i].key : full[i].group + "." + full[i].key] =
          scale > 0.0 ? difference / scale : 0.0;
    }
  }
  return d;
}

}  // namespace linkwright::kinematics
