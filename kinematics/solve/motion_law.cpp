#include "kinematics/solve/motion_law.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace linkwright::kinematics {
namespace {

constexpr double kTwoPi = 2.0 * kPi;

// A rise of `h` over `T` from `q0`, with the normalised profile s(u), s'(u), s''(u).
template <typename Profile>
DriverState rise(double q0, double h, double T, double t, Profile profile) {
  if (t <= 0.0) return {q0, 0.0, 0.0};
  if (t >= T) return {q0 + h, 0.0, 0.0};
  const auto [s, ds, dds] = profile(t / T);
  return {q0 + h * s, h * ds / T, h * dds / (T * T)};
}

struct StateAt {
  double t;
  DriverState operator()(const ConstantVelocity& l) const { return {l.start + l.velocity * t, l.velocity, 0.0}; }
  DriverState operator()(const RampToSpeed& l) const {
    if (t <= 0.0) return {l.start, 0.0, 0.0};
    const double a = l.velocity / l.rampTime;
    if (t <= l.rampTime) return {l.start + 0.5 * a * t * t, a * t, a};
    return {l.start + 0.5 * l.velocity * l.rampTime + l.velocity * (t - l.rampTime), l.velocity, 0.0};
  }
  DriverState operator()(const CycloidalRise& l) const {
    return rise(l.start, l.rise, l.duration, t, [](double u) {
      const double w = kTwoPi * u;
      return std::array<double, 3>{u - std::sin(w) / kTwoPi, 1.0 - std::cos(w), kTwoPi * std::sin(w)};
    });
  }
  DriverState operator()(const PolynomialRise& l) const {
    return rise(l.start, l.rise, l.duration, t, [](double u) {
      const double u2 = u * u;
      return std::array<double, 3>{u2 * u * (10.0 - 15.0 * u + 6.0 * u2), u2 * (30.0 - 60.0 * u + 30.0 * u2),
                                   u * (60.0 - 180.0 * u + 120.0 * u2)};
    });
  }
  DriverState operator()(const TableLaw& l) const {
    const std::vector<double>& x = l.time;
    const std::vector<double>& y = l.position;
    const std::vector<double>& m = l.curvature;
    // Outside its data the table holds its end; sweeps keep within it (checkSweepSpec).
    if (t < x.front()) return {y.front(), 0.0, 0.0};
    if (t > x.back()) return {y.back(), 0.0, 0.0};
    const auto after = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), t) - x.begin());
    const std::size_t i = std::min(after - 1, x.size() - 2);
    const double h = x[i + 1] - x[i];
    const double a = (x[i + 1] - t) / h;
    const double b = (t - x[i]) / h;
    return {a * y[i] + b * y[i + 1] + ((a * a * a - a) * m[i] + (b * b * b - b) * m[i + 1]) * h * h / 6.0,
            (y[i + 1] - y[i]) / h - (3.0 * a * a - 1.0) / 6.0 * h * m[i] + (3.0 * b * b - 1.0) / 6.0 * h * m[i + 1],
            a * m[i] + b * m[i + 1]};
  }
};

// The slope at x[at] of the cubic through the four points at indices `nodes`.
double cubicSlope(const std::vector<double>& x, const std::vector<double>& y, const std::array<std::size_t, 4>& nodes,
                  std::size_t at) {
  double slope = 0.0;
  for (const std::size_t j : nodes) {
    // d/dx of the Lagrange basis polynomial of node j, at x[at].
    double derivative = 0.0;
    if (j == at) {
      for (const std::size_t k : nodes)
        if (k != j) derivative += 1.0 / (x[j] - x[k]);
    } else {
      double numerator = 1.0, denominator = x[j] - x[at];
      for (const std::size_t k : nodes)
        if (k != j && k != at) {
          numerator *= x[at] - x[k];
          denominator *= x[j] - x[k];
        }
      derivative = numerator / denominator;
    }
    slope += y[j] * derivative;
  }
  return slope;
}

Error fieldError(const std::string& field, const std::string& why) {
  return Error{ErrorCode::InvalidValue, field, field + " " + why};
}

// A law's time: positive and finite, at most kMaxTime.

std::optional<Error> checkDuration(double value, const std::string& field) {
  if (value > 0.0 && value <= kMaxTime) return std::nullopt;
  return fieldError(field, "must be positive and at most 1e6 s (got " + formatNumber(value) + ")");
}

struct CheckLaw {
  InputDomain domain;

  // Bounds every law shares: the driver's speed and acceleration within the domain's. Both
  // are computed (a ramp's speed over its time), so never echoed as nan or inf.
  std::optional<Error> checkPeaks(double velocity, double acceleration) const {
    if (auto e = checkComputedMagnitude(velocity, "law peak velocity", domain.rate, domain.rateUnit)) return e;
    return checkComputedMagnitude(acceleration, "law peak acceleration", domain.acceleration, domain.accelerationUnit);
  }
  std::optional<Error> checkPosition(double value, const char* field) const {
    return checkMagnitude(value, field, domain.position, domain.positionUnit);
  }
  std::optional<Error> checkRise(double start, double rise, double duration) const {
    if (auto e = checkPosition(start, "law.start")) return e;
    if (auto e = checkPosition(rise, "law.rise")) return e;
    if (auto e = checkDuration(duration, "law.duration")) return e;
    // Cycloidal 2h/T and 2πh/T²; the 3-4-5 rise peaks lower (1.875h/T, 5.77h/T²).
    return checkPeaks(2.0 * rise / duration, kTwoPi * rise / (duration * duration));
  }

  std::optional<Error> operator()(const ConstantVelocity& l) const {
    if (auto e = checkPosition(l.start, "law.start")) return e;
    return checkPeaks(l.velocity, 0.0);
  }
  std::optional<Error> operator()(const RampToSpeed& l) const {
    if (auto e = checkPosition(l.start, "law.start")) return e;
    if (auto e = checkDuration(l.rampTime, "law.rampTime")) return e;
    return checkPeaks(l.velocity, l.velocity / l.rampTime);
  }
  std::optional<Error> operator()(const CycloidalRise& l) const { return checkRise(l.start, l.rise, l.duration); }
  std::optional<Error> operator()(const PolynomialRise& l) const { return checkRise(l.start, l.rise, l.duration); }
  std::optional<Error> operator()(const TableLaw& l) const {
    if (l.time.size() < 4 || l.position.size() != l.time.size() || l.curvature.size() != l.time.size())
      return fieldError("law.table", "needs at least four rows of time and position, as makeTableLaw builds");
    double peakVelocity = 0.0, peakAcceleration = 0.0;
    // The largest |value|, a NaN kept (std::max would drop it): an overflowed spline is refused.
    const auto grow = [](double& peak, double value) {
      if (!std::isnan(peak) && !(std::abs(value) <= peak)) peak = std::abs(value);
    };
    for (std::size_t i = 0; i + 1 < l.time.size(); ++i) {
      // q̈ is linear on each interval and q̇ quadratic: their extremes are at the ends or where q̈ = 0.
      const double t0 = l.time[i], t1 = l.time[i + 1];
      for (const double t : {t0, t1,
                             l.curvature[i] * l.curvature[i + 1] < 0.0
                                 ? t0 + (t1 - t0) * l.curvature[i] / (l.curvature[i] - l.curvature[i + 1])
                                 : t0}) {
        const DriverState s = StateAt{t}(l);
        grow(peakVelocity, s.velocity);
      }
      grow(peakAcceleration, l.curvature[i]);
      grow(peakAcceleration, l.curvature[i + 1]);
    }
    for (std::size_t i = 0; i < l.position.size(); ++i)
      if (auto e = checkPosition(l.position[i], "law.table position")) return e;
    return checkPeaks(peakVelocity, peakAcceleration);
  }
};

}  // namespace

DriverState motionAt(const MotionLaw& law, double t) { return std::visit(StateAt{t}, law); }

std::optional<Error> checkMotionLaw(const MotionLaw& law, InputKind kind) {
  return std::visit(CheckLaw{inputDomain(kind)}, law);
}

std::optional<std::pair<double, double>> lawTimeSpan(const MotionLaw& law) {
  if (const auto* table = std::get_if<TableLaw>(&law)) return std::pair{table->time.front(), table->time.back()};
  return std::nullopt;
}

Result<TableLaw> makeTableLaw(std::vector<double> time, std::vector<double> position) {
  const std::size_t n = time.size();
  if (position.size() != n)
    return fieldError("law.table", "has " + std::to_string(n) + " times but " + std::to_string(position.size()) +
                                       " positions: the two lists must have the same length, one position per time");
  if (n < 4)
    return fieldError("law.table", "needs at least four rows of time and position (got " + std::to_string(n) + ")");
  for (std::size_t i = 0; i < n; ++i) {
    const std::string row = "law.table[" + std::to_string(i) + "]";
    if (auto e = checkMagnitude(time[i], row + ".time", kMaxTime, "s")) return *e;
    // The widest domain here; checkMotionLaw holds the rows to the driver's own.
    if (auto e = checkMagnitude(position[i], row + ".position", kMaxLength, "")) return *e;
    if (i > 0 && !(time[i] > time[i - 1]))
      return fieldError(row + ".time", "must be later than the row before (got " + formatNumber(time[i]) + " after " +
                                           formatNumber(time[i - 1]) + ")");
  }
  // A clamped spline, its end slopes those of the cubic through the four end points, so that
  // a cubic is reproduced exactly. Second derivatives M solve a tridiagonal system (Thomas).
  const std::vector<double>& x = time;
  const std::vector<double>& y = position;
  const double startSlope = cubicSlope(x, y, {0, 1, 2, 3}, 0);
  const double endSlope = cubicSlope(x, y, {n - 4, n - 3, n - 2, n - 1}, n - 1);
  std::vector<double> lower(n, 0.0), diagonal(n, 0.0), upper(n, 0.0), rhs(n, 0.0);
  const auto h = [&x](std::size_t i) { return x[i + 1] - x[i]; };
  const auto secant = [&](std::size_t i) { return (y[i + 1] - y[i]) / h(i); };
  diagonal[0] = 2.0 * h(0);
  upper[0] = h(0);
  rhs[0] = 6.0 * (secant(0) - startSlope);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    lower[i] = h(i - 1);
    diagonal[i] = 2.0 * (h(i - 1) + h(i));
    upper[i] = h(i);
    rhs[i] = 6.0 * (secant(i) - secant(i - 1));
  }
  lower[n - 1] = h(n - 2);
  diagonal[n - 1] = 2.0 * h(n - 2);
  rhs[n - 1] = 6.0 * (endSlope - secant(n - 2));
  for (std::size_t i = 1; i < n; ++i) {  // diagonally dominant: no pivoting needed
    const double w = lower[i] / diagonal[i - 1];
    diagonal[i] -= w * upper[i - 1];
    rhs[i] -= w * rhs[i - 1];
  }
  std::vector<double> curvature(n, 0.0);
  curvature[n - 1] = rhs[n - 1] / diagonal[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) curvature[i] = (rhs[i] - upper[i] * curvature[i + 1]) / diagonal[i];
  return TableLaw{std::move(time), std::move(position), std::move(curvature)};
}

}  // namespace linkwright::kinematics
