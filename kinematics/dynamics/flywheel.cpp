#include "kinematics/dynamics/flywheel.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;
constexpr std::size_t kStepsPerSample = 4;
constexpr int kMaxIterations = 100;

// The energy equation's pieces as series: W(θ) = ∫θ₀^θ (T̄ − T_s) and I_eq(θ).
struct EnergyTerms {
  PeriodicSeries surplus;  // of T_s: W = −surplus
  PeriodicSeries inertia;
  double target;  // |ω|
  explicit EnergyTerms(const CrankTerms& t)
      : surplus(t.staticSeries().surplusSeries()), inertia(t.inertiaSeries()), target(std::abs(t.omega)) {}

  double w(double theta) const { return -surplus.value(theta); }
  double speed(double theta, double flywheel, double k0) const {
    return std::sqrt(std::max(0.0, 2.0 * (k0 + w(theta)) / (flywheel + inertia.value(theta))));
  }
  std::vector<double> sampleSpeeds(double flywheel, double k0) const {
    std::vector<double> s(surplus.size());
    for (std::size_t j = 0; j < s.size(); ++j)
      s[j] = std::sqrt(std::max(0.0, 2.0 * (k0 - surplus.samples()[j]) / (flywheel + inertia.samples()[j])));
    return s;
  }
  // The slowest and fastest |θ̇|, refined between samples.
  std::pair<double, double> range(double flywheel, double k0) const {
    std::vector<double> s = sampleSpeeds(flywheel, k0);
    const auto f = [&](double theta) { return speed(theta, flywheel, k0); };
    const double fastest = refinePeriodicMaximum(f, surplus.theta0(), s).value;
    for (double& v : s) v = -v;
    const double slowest = -refinePeriodicMaximum([&](double theta) { return -f(theta); }, surplus.theta0(), s).value;
    return {slowest, fastest};
  }
  double midSpeed(double flywheel, double k0) const {
    const auto [slowest, fastest] = range(flywheel, k0);
    return 0.5 * (slowest + fastest);
  }
  // K₀ that makes the mean speed (ω_max + ω_min)/2 the turn's |ω|, by secant iterations.
  double startEnergy(double flywheel) const {
    const double floor = surplus.maximum().value;  // K₀ above −min W keeps K ≥ 0
    double k0 = std::max(0.5 * (flywheel + inertia.samples().front()) * target * target, 1.01 * floor);
    double k1 = 1.001 * k0 + 1e-300;
    double m0 = midSpeed(flywheel, k0) - target;
    double m1 = midSpeed(flywheel, k1) - target;
    for (int i = 0; i < kMaxIterations && std::abs(m1) > 1e-13 * target && m1 != m0; ++i) {
      const double k2 = std::max(k1 - m1 * (k1 - k0) / (m1 - m0), floor);
      k0 = k1;
      m0 = m1;
      k1 = k2;
      m1 = midSpeed(flywheel, k1) - target;
    }
    return k1;
  }
};

struct State {
  double theta;
  double omega;
};

}  // namespace

FlywheelSpeeds flywheelSpeeds(const CrankTerms& t, double flywheel) {
  const EnergyTerms e(t);
  const double k0 = e.startEnergy(flywheel);
  FlywheelSpeeds s;
  s.speed = e.sampleSpeeds(flywheel, k0);
  s.speed.push_back(s.speed.front());  // the closing sample, as the terms have it
  if (t.omega < 0.0)
    for (double& v : s.speed) v = -v;
  std::tie(s.slowest, s.fastest) = e.range(flywheel, k0);
  return s;
}

double FlywheelRun::slowest() const {
  if (speed.empty()) return 0.0;
  double least = std::abs(speed.front());
  for (const double v : speed) least = std::min(least, std::abs(v));
  return least;
}

double FlywheelRun::fastest() const {
  double most = 0.0;
  for (const double v : speed) most = std::max(most, std::abs(v));
  return most;
}

std::optional<Error> checkSpeedFluctuation(double cs) {
  if (cs >= kMinSpeedFluctuation && cs <= kMaxSpeedFluctuation) return std::nullopt;
  return Error{ErrorCode::InvalidValue, "cs",
               "the coefficient of speed fluctuation Cs must be from 1e-5 to 0.9 (got " + formatNumber(cs) + ")"};
}

Result<double> sizeFlywheel(const CrankTerms& t, double cs) {
  if (auto e = checkSpeedFluctuation(cs)) return *e;
  const double meanInertia = t.inertiaSeries().mean();
  if (flywheelSpeeds(t, 0.0).fluctuation() <= cs) return 0.0;
  // The textbook flywheel, ΔE/(Cs ω²), to start.
  const PeriodicSeries surplus = t.staticSeries().surplusSeries();
  const double energy = surplus.maximum().value - surplus.minimum().value;
  double flywheel = std::max(energy / (cs * t.omega * t.omega), 1e-12 * meanInertia);
  for (int i = 0; i < kMaxIterations; ++i) {
    const double got = flywheelSpeeds(t, flywheel).fluctuation();
    if (std::abs(got - cs) <= 1e-10 * cs) return flywheel;
    flywheel = std::max((flywheel + meanInertia) * got / cs - meanInertia, 0.5 * flywheel);
  }
  return Error{ErrorCode::InvalidValue, "cs",
               "no flywheel was found that holds the speed within Cs = " + formatShort(cs) +
                   " (the iteration did not converge)"};
}

Result<FlywheelRun> runFlywheel(const CrankTerms& t, double flywheel) {
  if (!(flywheel >= 0.0 && flywheel <= kMaxInertia))
    return Error{ErrorCode::InvalidValue, "flywheel inertia",
                 "the flywheel inertia must be between 0 and 1e27 kg·m² (got " + formatNumber(flywheel) + ")"};
  const PeriodicSeries staticTorque = t.staticSeries(), halfSlope = t.halfSlopeSeries(), inertia = t.inertiaSeries();
  const double meanTorque = staticTorque.mean();
  const auto acceleration = [&](const State& s) {
    return (meanTorque - staticTorque.value(s.theta) - halfSlope.value(s.theta) * s.omega * s.omega) /
           (flywheel + inertia.value(s.theta));
  };
  const std::size_t steps = std::min((t.angle.size() - 1) * kStepsPerSample, kMostRunSteps);
  const double dt = kTurn / std::abs(t.omega) / static_cast<double>(steps);
  const double start = t.omega > 0.0 ? t.angle.front() : t.angle.back();
  const std::vector<double> speeds = flywheelSpeeds(t, flywheel).speed;
  State s{start, t.omega > 0.0 ? speeds.front() : speeds.back()};
  FlywheelRun run;
  // Until the crank has turned once; a crank that stalls stops the run at twice the turn's time.
  for (std::size_t k = 0; k <= 2 * steps; ++k) {
    run.time.push_back(static_cast<double>(k) * dt);
    run.angle.push_back(s.theta);
    run.speed.push_back(s.omega);
    if (std::abs(s.theta - start) >= kTurn) break;
    const State k1{s.omega, acceleration(s)};
    const State k2{s.omega + 0.5 * dt * k1.omega,
                   acceleration({s.theta + 0.5 * dt * k1.theta, s.omega + 0.5 * dt * k1.omega})};
    const State k3{s.omega + 0.5 * dt * k2.omega,
                   acceleration({s.theta + 0.5 * dt * k2.theta, s.omega + 0.5 * dt * k2.omega})};
    const State k4{s.omega + dt * k3.omega, acceleration({s.theta + dt * k3.theta, s.omega + dt * k3.omega})};
    s.theta += dt / 6.0 * (k1.theta + 2.0 * k2.theta + 2.0 * k3.theta + k4.theta);
    s.omega += dt / 6.0 * (k1.omega + 2.0 * k2.omega + 2.0 * k3.omega + k4.omega);
  }
  const auto [low, high] = std::minmax_element(run.speed.begin(), run.speed.end());
  run.meanSpeed = 0.5 * (*low + *high);
  run.speedFluctuation = (*high - *low) / std::abs(run.meanSpeed);
  return run;
}

}  // namespace linkwright::kinematics
