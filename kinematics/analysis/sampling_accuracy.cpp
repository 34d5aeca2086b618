#include "kinematics/analysis/sampling_accuracy.h"

#include "kinematics/analysis/extrema.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * kPi;

double wrap(double angle) { return std::remainder(angle, kTurn); }

bool isGround(const Mechanism& m, std::size_t i) { return std::holds_alternative<GroundPoint>(m.points[i].definition); }

// One turn, N samples from 0 (the last one short of 2π: the cycle is periodic).
Result<SweepResult> oneTurn(const Mechanism& m, double omega, std::size_t n, const SolveRequest& request) {
  auto r = sweep(m, {0.0, kTurn * static_cast<double>(n - 1) / static_cast<double>(n), n, omega, 0.0}, request);
  if (r && !r->notAssembled.empty())
    return Error{ErrorCode::NotAssemblable, "crank",
                 "the crank must turn fully to measure peaks over a cycle: " + r->firstFailure.value_or("it does not")};
  return r;
}

std::size_t allocate(const Mechanism& m, PeakSet& p) {
  const std::size_t links = m.links.size();
  p.linkOmega.assign(links, 0.0);
  p.linkAlpha.assign(links, 0.0);
  p.linkMinAngle.assign(links, 0.0);
  p.linkMaxAngle.assign(links, 0.0);
  p.linkRocks.assign(links, false);
  p.pointSpeed.assign(m.points.size(), 0.0);
  p.pointAcceleration.assign(m.points.size(), 0.0);
  return links;
}

// A link rocks unless its unwrapped angle gains a whole turn over the cycle.
bool rocks(const std::vector<double>& angle, double lastStep) {
  return std::abs(angle.back() + lastStep - angle.front()) < kPi;
}

double maxAbs(const Extrema& e) { return std::max(std::abs(e.minimum.value), std::abs(e.maximum.value)); }

// What both ways of finding the peaks accept: a valid mechanism, a positive ω in its domain,
// at least three samples a turn.
std::optional<Error> checkPeakInputs(const Mechanism& m, double omega, std::size_t n) {
  if (auto e = checkMechanism(m)) return e;
  if (!(omega > 0.0))
    return Error{ErrorCode::InvalidValue, "omega", "omega must be positive (got " + formatNumber(omega) + ")"};
  if (auto e = checkMagnitude(omega, "omega", kMaxOmega, "rad/s")) return e;
  if (n < 3)
    return Error{ErrorCode::InvalidValue, "samples",
                 "samples per revolution must be at least 3 (got " + std::to_string(n) + ")"};
  return std::nullopt;
}

}  // namespace

double PeakError::worstRate() const { return std::max({omega, alpha, speed, acceleration}); }

Result<PeakSet> exactPeaks(const Mechanism& m, double omega, std::size_t n) {
  if (auto e = checkPeakInputs(m, omega, n)) return *e;
  const SweepSpec spec{0.0, kTurn, n + 1, omega, 0.0};
  const auto full = sweep(m, spec);
  if (!full) return full.error();
  if (!full->notAssembled.empty())
    return Error{
        ErrorCode::NotAssemblable, "crank",
        "the crank must turn fully to measure peaks over a cycle: " + full->firstFailure.value_or("it does not")};
  PeakSet p;
  const std::size_t links = allocate(m, p);
  std::vector<bool> valid(full->size());
  for (std::size_t j = 0; j < full->size(); ++j) valid[j] = full->ok(j);
  const auto refine = [&](const std::vector<double>& values, const PoseQuantity& q) {
    return refineExtrema(m, spec, values, valid, q, 1e-12);
  };
  for (std::size_t k = 0; k < links; ++k) {
    if (kinematics::isDrivenCrankLink(m, LinkId{k})) continue;
    if (const auto w = refine(full->linkOmega[k], [k](const Pose& x, double) { return x.linkOmega[k]; }))
      p.linkOmega[k] = maxAbs(*w);
    if (const auto a = refine(full->linkAlpha[k], [k](const Pose& x, double) { return x.linkAlpha[k]; }))
      p.linkAlpha[k] = maxAbs(*a);
    p.linkRocks[k] = rocks(full->linkAngle[k], 0.0);  // the sweep ends where it began, at 2π
    if (!p.linkRocks[k]) continue;
    // Unwrapped angles near the sweep's start: refine the raw (wrapped) angle about that branch.
    const double base = full->linkAngle[k].front();
    const auto angle =
        refine(full->linkAngle[k], [k, base](const Pose& x, double) { return base + wrap(x.linkAngle[k] - base); });
    if (angle) {
      p.linkMinAngle[k] = angle->minimum.value;
      p.linkMaxAngle[k] = angle->maximum.value;
    }
  }
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (isGround(m, i)) continue;
    std::vector<double> speed(full->size()), accel(full->size());
    for (std::size_t j = 0; j < full->size(); ++j) {
      speed[j] = full->velocity[i][j].norm();
      accel[j] = full->acceleration[i][j].norm();
    }
    if (const auto v = refine(speed, [i](const Pose& x, double) { return x.velocity[i].norm(); }))
      p.pointSpeed[i] = v->maximum.value;
    if (const auto a = refine(accel, [i](const Pose& x, double) { return x.acceleration[i].norm(); }))
      p.pointAcceleration[i] = a->maximum.value;
  }
  return p;
}

Result<PeakSet> sampledPeaks(const Mechanism& m, double omega, std::size_t n, DerivativeMethod method,
                             const NewtonSettings& newton) {
  if (auto e = checkPeakInputs(m, omega, n)) return *e;
  const bool exact = method == DerivativeMethod::Exact;
  const auto s = oneTurn(m, omega, n, SolveRequest{exact, exact, newton});
  if (!s) return s.error();
  const double dt = kTurn / static_cast<double>(n) / omega;
  const auto prev = [n](std::size_t j) { return (j + n - 1) % n; };
  const auto next = [n](std::size_t j) { return (j + 1) % n; };
  PeakSet p;
  const std::size_t links = allocate(m, p);
  for (std::size_t k = 0; k < links; ++k) {
    if (kinematics::isDrivenCrankLink(m, LinkId{k})) continue;
    const auto& a = s->linkAngle[k];
    for (std::size_t j = 0; j < n; ++j) {
      const double w = exact ? s->linkOmega[k][j] : wrap(a[next(j)] - a[prev(j)]) / (2.0 * dt);
      const double al = exact ? s->linkAlpha[k][j] : (wrap(a[next(j)] - a[j]) - wrap(a[j] - a[prev(j)])) / (dt * dt);
      p.linkOmega[k] = std::max(p.linkOmega[k], std::abs(w));
      p.linkAlpha[k] = std::max(p.linkAlpha[k], std::abs(al));
    }
    p.linkRocks[k] = rocks(a, wrap(a.front() - a.back()));
    if (!p.linkRocks[k]) continue;
    const auto [lo, hi] = std::minmax_element(a.begin(), a.end());
    const double base = a.front();  // the exact peaks are expressed about the first sample's angle
    p.linkMinAngle[k] = base + wrap(*lo - base);
    p.linkMaxAngle[k] = base + wrap(*hi - base);
  }
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (isGround(m, i)) continue;
    const auto& x = s->position[i];
    for (std::size_t j = 0; j < n; ++j) {
      const Eigen::Vector2d v = exact ? s->velocity[i][j] : Eigen::Vector2d((x[next(j)] - x[prev(j)]) / (2.0 * dt));
      const Eigen::Vector2d acc =
          exact ? s->acceleration[i][j] : Eigen::Vector2d((x[next(j)] - 2.0 * x[j] + x[prev(j)]) / (dt * dt));
      p.pointSpeed[i] = std::max(p.pointSpeed[i], v.norm());
      p.pointAcceleration[i] = std::max(p.pointAcceleration[i], acc.norm());
    }
  }
  return p;
}

PeakError peakError(const PeakSet& read, const PeakSet& exact) {
  PeakError e;
  const auto relative = [](double r, double x) { return x > 0.0 ? std::abs(r - x) / x : 0.0; };
  for (std::size_t k = 0; k < exact.linkOmega.size(); ++k) {
    e.omega = std::max(e.omega, relative(read.linkOmega[k], exact.linkOmega[k]));
    e.alpha = std::max(e.alpha, relative(read.linkAlpha[k], exact.linkAlpha[k]));
    if (!exact.linkRocks[k]) continue;
    e.angle = std::max({e.angle, std::abs(read.linkMinAngle[k] - exact.linkMinAngle[k]),
                        std::abs(read.linkMaxAngle[k] - exact.linkMaxAngle[k])});
  }
  for (std::size_t i = 0; i < exact.pointSpeed.size(); ++i) {
    e.speed = std::max(e.speed, relative(read.pointSpeed[i], exact.pointSpeed[i]));
    e.acceleration = std::max(e.acceleration, relative(read.pointAcceleration[i], exact.pointAcceleration[i]));
  }
  return e;
}

}  // namespace linkwright::kinematics
