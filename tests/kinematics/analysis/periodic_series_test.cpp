// The trigonometric interpolant of a turn's samples against closed forms: its mean, its
// integral and its refined extremes of smooth periodic functions converge to round-off from a
// few dozen samples, where the trapezoidal surplus and the best sample do not; and halfGrid's
// estimate bounds the error it claims to.

#include "kinematics/analysis/periodic_series.h"

#include "tests/support/catch.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

using namespace linkwright::kinematics;

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

std::vector<double> sampled(const std::function<double(double)>& f, double theta0, std::size_t n) {
  std::vector<double> s(n);
  for (std::size_t j = 0; j < n; ++j) s[j] = f(theta0 + kTurn * static_cast<double>(j) / static_cast<double>(n));
  return s;
}

// e^{cos φ}: mean I₀(1), maximum e at φ = 0, minimum 1/e at φ = π; analytic, so every
// coefficient counts and none is exactly zero.
double besselI0of1() {
  double sum = 0.0, term = 1.0;
  for (int k = 0; k < 30; ++k) {
    if (k > 0) term *= 0.25 / (static_cast<double>(k) * static_cast<double>(k));
    sum += term;
  }
  return sum;
}

}  // namespace

TEST_CASE("the series of e^cos(θ − 1) has the exact mean and extremes from 36 samples", "[analysis][periodic]") {
  const double shift = 1.0, theta0 = 0.3;
  const auto f = [&](double t) { return std::exp(std::cos(t - shift)); };
  const PeriodicSeries s(theta0, sampled(f, theta0, 36));
  CHECK(s.mean() == Approx(besselI0of1()).epsilon(1e-14));
  const PeriodicPeak high = s.maximum(), low = s.minimum();
  CHECK(high.value == Approx(std::exp(1.0)).epsilon(1e-14));
  CHECK(high.at == Approx(shift).margin(1e-7));
  CHECK(low.value == Approx(std::exp(-1.0)).epsilon(1e-14));
  CHECK(low.at == Approx(shift + std::numbers::pi).margin(1e-7));
  // Between samples the interpolant is the function to round-off.
  for (double t : {0.31, 1.7, 4.0, 6.2}) CHECK(s.value(t) == Approx(f(t)).epsilon(1e-14));
  // The best of 36 samples falls short of the maximum: the refinement counts.
  double bestSample = 0.0;
  for (double v : s.samples()) bestSample = std::max(bestSample, v);
  CHECK(std::exp(1.0) - bestSample > 1e-6);
}

TEST_CASE("the surplus integral of a series is its exact integral", "[analysis][periodic]") {
  // f = 2 + 3 cos θ − sin 2θ + 0.5 cos 5θ: ∫₀^θ (f − 2) = 3 sin θ + (cos 2θ − 1)/2 + 0.1 sin 5θ.
  const auto f = [](double t) { return 2.0 + 3.0 * std::cos(t) - std::sin(2.0 * t) + 0.5 * std::cos(5.0 * t); };
  const auto exact = [](double t) {
    return 3.0 * std::sin(t) + 0.5 * (std::cos(2.0 * t) - 1.0) + 0.1 * std::sin(5.0 * t);
  };
  for (std::size_t n : {12, 13, 360}) {
    CAPTURE(n);
    const PeriodicSeries s(0.0, sampled(f, 0.0, n));
    CHECK(s.mean() == Approx(2.0).epsilon(1e-14));
    for (double t : {0.0, 0.4, 2.0, 3.9, 6.0}) CHECK(s.surplusIntegral(t) == Approx(exact(t)).margin(1e-13));
    const PeriodicSeries e = s.surplusSeries();
    // Its samples (by the inverse transform) are its values there.
    for (std::size_t j = 0; j < n; ++j) CHECK(e.samples()[j] == Approx(e.value(e.sampleAngle(j))).margin(1e-13));
    CHECK(e.mean() == Approx(0.5 * (0.0 - 1.0)).margin(1e-13));  // the mean of the exact integral
    // Its extremes against a dense scan of the closed form.
    double high = -1e9, low = 1e9;
    for (int i = 0; i <= 2000000; ++i) {
      const double v = exact(kTurn * i / 2000000.0);
      high = std::max(high, v);
      low = std::min(low, v);
    }
    CHECK(e.maximum().value == Approx(high).epsilon(1e-11));
    CHECK(e.minimum().value == Approx(low).epsilon(1e-11));
  }
}

TEST_CASE("the surplus of e^cos θ starts from a non-zero turn angle", "[analysis][periodic]") {
  // From θ₀ = 2 the surplus is ∫₂^θ (e^{cos φ} − I₀(1)) dφ; Simpson's rule on 2·10⁵ intervals
  // is exact to ~1e-18 here.
  const double theta0 = 2.0;
  const auto f = [](double t) { return std::exp(std::cos(t)); };
  const PeriodicSeries s(theta0, sampled(f, theta0, 48));
  const double to = theta0 + 2.5, mean = besselI0of1();
  const int m = 200000;
  const double h = (to - theta0) / m;
  double simpson = 0.0;
  for (int i = 0; i < m; ++i) {
    const double a = theta0 + i * h;
    simpson += h / 6.0 * ((f(a) - mean) + 4.0 * (f(a + 0.5 * h) - mean) + (f(a + h) - mean));
  }
  CHECK(s.surplusIntegral(to) == Approx(simpson).margin(1e-13));
  CHECK(s.surplusIntegral(theta0) == Approx(0.0).margin(1e-15));
}

TEST_CASE("halfGrid's difference bounds the error of a slowly converging series", "[analysis][periodic]") {
  // |sin(θ/2)|³ has a jump in its third derivative at θ = 0: the series converges as N⁻⁴, so
  // the mean read off N samples is wrong, and the same mean off N/2 samples says by how much.
  const auto f = [](double t) { return std::pow(std::abs(std::sin(0.5 * t)), 3); };
  const double exact = 4.0 / (3.0 * std::numbers::pi);  // (1/2π)∮|sin(θ/2)|³ = 4/(3π)
  for (std::size_t n : {14, 30, 62}) {
    CAPTURE(n);
    const PeriodicSeries s(0.1, sampled(f, 0.1, n));
    const double error = std::abs(s.mean() - exact);
    const double estimate = std::abs(s.mean() - s.halfGrid().mean());
    CHECK(error > 1e-9);  // not converged: the estimate has work to do
    CHECK(error <= estimate);
  }
}

TEST_CASE("the maximum of a vector's norm is refined between samples", "[analysis][periodic]") {
  // F = (3 cos θ, 2 sin θ + 1): |F|² = 9 cos² + (2 sin + 1)² peaks at sin θ = 2/5 with 9 + 4/5 + …
  const auto fx = [](double t) { return 3.0 * std::cos(t); };
  const auto fy = [](double t) { return 2.0 * std::sin(t) + 1.0; };
  const std::size_t n = 24;
  const PeriodicSeries x(0.0, sampled(fx, 0.0, n)), y(0.0, sampled(fy, 0.0, n));
  std::vector<double> norms(n);
  for (std::size_t j = 0; j < n; ++j) norms[j] = std::hypot(x.samples()[j], y.samples()[j]);
  const PeriodicPeak peak =
      refinePeriodicMaximum([&](double t) { return std::hypot(x.value(t), y.value(t)); }, 0.0, norms);
  // d|F|²/dθ = −18 cos sin + 4 (2 sin + 1) cos = cos θ (−10 sin θ + 4) = 0 at sin θ = 0.4.
  const double s = 0.4, c = std::sqrt(1.0 - s * s);
  CHECK(peak.value == Approx(std::hypot(3.0 * c, 2.0 * s + 1.0)).epsilon(1e-14));
  CHECK(peak.at == Approx(std::asin(s)).margin(1e-7));
}
