#include "kinematics/dynamics/flywheel.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;
constexpr int kStepsPerSample = 4;
constexpr int kMaxIterations = 100;

// W(θ_j) = ∫ (T̄ − T_s) dθ from the first sample, T̄ the mean of T_s so that W closes the turn.
std::vector<double> surplus(const CrankTerms& t) {
  const double mean = t.mean(t.staticTorque);
  std::vector<double> w(t.angle.size(), 0.0);
  for (std::size_t i = 1; i < w.size(); ++i)
    w[i] = w[i - 1] + 0.5 * (2.0 * mean - t.staticTorque[i - 1] - t.staticTorque[i]) * (t.angle[i] - t.angle[i - 1]);
  return w;
}

// |θ̇| at each sample for the kinetic energy K₀ + W at the first one; 0 where K would be below 0.
std::vector<double> speedsFor(const CrankTerms& t, const std::vector<double>& w, double flywheel, double k0) {
  std::vector<double> s(w.size());
  for (std::size_t j = 0; j < w.size(); ++j)
    s[j] = std::sqrt(std::max(0.0, 2.0 * (k0 + w[j]) / (flywheel + t.inertia[j])));
  return s;
}

double midSpeed(const std::vector<double>& s) {
  const auto [low, high] = std::minmax_element(s.begin(), s.end());
  return 0.5 * (*low + *high);
}

struct State {
  double theta;
  double omega;
};

}  // namespace

std::vector<double> flywheelSpeeds(const CrankTerms& t, double flywheel) {
  const std::vector<double> w = surplus(t);
  const double target = std::abs(t.omega);
  const double floor = -*std::min_element(w.begin(), w.end());  // K₀ above it keeps K ≥ 0
  double k0 = std::max(0.5 * (flywheel + t.inertia.front()) * target * target, 1.01 * floor);
  double k1 = 1.001 * k0 + 1e-300;
  double m0 = midSpeed(speedsFor(t, w, flywheel, k0)) - target;
  double m1 = midSpeed(speedsFor(t, w, flywheel, k1)) - target;
  for (int i = 0; i < kMaxIterations && std::abs(m1) > 1e-13 * target && m1 != m0; ++i) {
    const double k2 = std::max(k1 - m1 * (k1 - k0) / (m1 - m0), floor);
    k0 = k1;
    m0 = m1;
    k1 = k2;
    m1 = midSpeed(speedsFor(t, w, flywheel, k1)) - target;
  }
  std::vector<double> s = speedsFor(t, w, flywheel, k1);
  if (t.omega < 0.0)
    for (double& v : s) v = -v;
  return s;
}

double speedFluctuation(const std::vector<double>& speeds) {
  const auto [low, high] = std::minmax_element(speeds.begin(), speeds.end());
  const double mid = 0.5 * (*low + *high);
  return (*high - *low) / std::abs(mid);
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
  if (cs > 0.0 && cs < 1.0) return std::nullopt;
  return Error{
      ErrorCode::InvalidValue, "cs",
      "the coefficient of speed fluctuation Cs must be between 0 and 1, exclusive (got " + formatNumber(cs) + ")"};
}

Result<double> sizeFlywheel(const CrankTerms& t, double cs) {
  if (auto e = checkSpeedFluctuation(cs)) return *e;
  const double meanInertia = t.mean(t.inertia);
  if (speedFluctuation(flywheelSpeeds(t, 0.0)) <= cs) return 0.0;
  // The textbook flywheel, ΔE/(Cs ω²), to start.
  const std::vector<double> w = surplus(t);
  const auto [low, high] = std::minmax_element(w.begin(), w.end());
  double flywheel = std::max((*high - *low) / (cs * t.omega * t.omega), 1e-12 * meanInertia);
  for (int i = 0; i < kMaxIterations; ++i) {
    const double got = speedFluctuation(flywheelSpeeds(t, flywheel));
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
  const double meanTorque = t.mean(t.staticTorque);
  const auto acceleration = [&](const State& s) {
    return (meanTorque - t.at(t.staticTorque, s.theta) - t.at(t.halfSlope, s.theta) * s.omega * s.omega) /
           (flywheel + t.at(t.inertia, s.theta));
  };
  const std::size_t steps = (t.angle.size() - 1) * kStepsPerSample;
  const double dt = kTurn / std::abs(t.omega) / static_cast<double>(steps);
  const double start = t.omega > 0.0 ? t.angle.front() : t.angle.back();
  const std::vector<double> speeds = flywheelSpeeds(t, flywheel);
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
