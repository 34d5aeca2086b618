#include "kinematics/analysis/periodic_series.h"

#include "kinematics/solve/golden_section.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace linkwright::kinematics {
namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;
constexpr double kAngleTolerance = 1e-10;  // rad, the golden-section search's bracket at the end
constexpr std::size_t kMostBrackets = 8;   // the highest local maxima searched
constexpr double kNegligible = 1e-17;      // a coefficient below this share of the largest is dropped
constexpr std::size_t kExactEvery = 64;    // the cos/sin recurrence restarts from std::cos/sin this often

// The series' values at the n samples of its grid, by the inverse transform: O(n log n), where
// evaluating it at each sample would be O(n K).
std::vector<double> gridValues(std::size_t n, const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<std::complex<double>> spectrum(n, 0.0);
  const double half = 0.5 * static_cast<double>(n);
  spectrum[0] = static_cast<double>(n) * a[0];
  for (std::size_t k = 1; k < a.size() && k < n; ++k) {
    if (n % 2 == 0 && 2 * k == n) {
      spectrum[k] = static_cast<double>(n) * a[k];  // the Nyquist term's sine is 0 at every sample
      continue;
    }
    if (2 * k > n) break;
    spectrum[k] = half * std::complex<double>(a[k], -b[k]);
    spectrum[n - k] = std::conj(spectrum[k]);
  }
  std::vector<double> values;
  Eigen::FFT<double> fft;
  fft.inv(values, spectrum);
  return values;
}

double foldIntoTurn(double theta, double theta0) {
  double t = std::fmod(theta - theta0, kTurn);
  if (t < 0.0) t += kTurn;
  return theta0 + t;
}

}  // namespace

PeriodicSeries::PeriodicSeries(double theta0, std::vector<double> samples)
    : m_theta0(theta0), m_samples(std::move(samples)) {
  const std::size_t n = m_samples.size();
  std::vector<std::complex<double>> spectrum;
  Eigen::FFT<double> fft;
  fft.fwd(spectrum, m_samples);
  const std::size_t top = n / 2;  // the Nyquist index at an even n, the last pair at an odd one
  m_a.assign(top + 1, 0.0);
  m_b.assign(top + 1, 0.0);
  const double scale = 1.0 / static_cast<double>(n);
  m_a[0] = spectrum[0].real() * scale;
  for (std::size_t k = 1; k <= top; ++k) {
    const bool nyquist = n % 2 == 0 && k == top;
    m_a[k] = (nyquist ? 1.0 : 2.0) * spectrum[k].real() * scale;
    m_b[k] = nyquist ? 0.0 : -2.0 * spectrum[k].imag() * scale;
  }
  double largest = 0.0;
  for (std::size_t k = 0; k <= top; ++k) largest = std::max({largest, std::abs(m_a[k]), std::abs(m_b[k])});
  std::size_t keep = top;
  while (keep > 0 && std::abs(m_a[keep]) + std::abs(m_b[keep]) <= kNegligible * largest) --keep;
  m_a.resize(keep + 1);
  m_b.resize(keep + 1);
}

PeriodicSeries::PeriodicSeries(double theta0, std::vector<double> samples, std::vector<double> a, std::vector<double> b)
    : m_theta0(theta0), m_samples(std::move(samples)), m_a(std::move(a)), m_b(std::move(b)) {}

double PeriodicSeries::sampleAngle(std::size_t j) const {
  return m_theta0 + kTurn * static_cast<double>(j) / static_cast<double>(m_samples.size());
}

double PeriodicSeries::value(double theta) const {
  const double phi = theta - m_theta0;
  const double c1 = std::cos(phi), s1 = std::sin(phi);
  double c = 1.0, s = 0.0, sum = m_a[0];
  for (std::size_t k = 1; k < m_a.size(); ++k) {
    if (k % kExactEvery == 0) {
      c = std::cos(static_cast<double>(k) * phi);
      s = std::sin(static_cast<double>(k) * phi);
    } else {
      const double next = c * c1 - s * s1;
      s = s * c1 + c * s1;
      c = next;
    }
    sum += m_a[k] * c + m_b[k] * s;
  }
  return sum;
}

PeriodicSeries PeriodicSeries::surplusSeries() const {
  // ∫₀^φ (a_k cos kφ' + b_k sin kφ') dφ' = (a_k/k) sin kφ + (b_k/k)(1 − cos kφ).
  std::vector<double> a(m_a.size(), 0.0), b(m_b.size(), 0.0);
  for (std::size_t k = 1; k < m_a.size(); ++k) {
    const double kk = static_cast<double>(k);
    a[k] = -m_b[k] / kk;
    b[k] = m_a[k] / kk;
    a[0] += m_b[k] / kk;
  }
  std::vector<double> values = gridValues(m_samples.size(), a, b);
  return PeriodicSeries(m_theta0, std::move(values), std::move(a), std::move(b));
}

double PeriodicSeries::surplusIntegral(double theta) const { return surplusSeries().value(theta); }

PeriodicPeak PeriodicSeries::maximum() const {
  return refinePeriodicMaximum([this](double theta) { return value(theta); }, m_theta0, m_samples);
}

PeriodicPeak PeriodicSeries::minimum() const {
  std::vector<double> negated(m_samples.size());
  std::transform(m_samples.begin(), m_samples.end(), negated.begin(), [](double v) { return -v; });
  PeriodicPeak peak = refinePeriodicMaximum([this](double theta) { return -value(theta); }, m_theta0, negated);
  peak.value = -peak.value;
  return peak;
}

PeriodicSeries PeriodicSeries::halfGrid() const {
  if (m_samples.size() < 4 || m_samples.size() % 2 != 0) return *this;
  std::vector<double> half(m_samples.size() / 2);
  for (std::size_t j = 0; j < half.size(); ++j) half[j] = m_samples[2 * j];
  return PeriodicSeries(m_theta0, std::move(half));
}

PeriodicPeak refinePeriodicMaximum(const std::function<double(double)>& f, double theta0,
                                   const std::vector<double>& samples) {
  const std::size_t n = samples.size();
  const double step = kTurn / static_cast<double>(n);
  std::vector<std::size_t> brackets;
  for (std::size_t j = 0; j < n; ++j)
    if (samples[j] >= samples[(j + n - 1) % n] && samples[j] >= samples[(j + 1) % n]) brackets.push_back(j);
  const std::size_t searched = std::min(kMostBrackets, brackets.size());
  std::partial_sort(brackets.begin(), brackets.begin() + static_cast<std::ptrdiff_t>(searched), brackets.end(),
                    [&](std::size_t l, std::size_t r) { return samples[l] > samples[r]; });
  PeriodicPeak best{samples.front(), theta0};
  for (std::size_t j = 0; j < n; ++j)
    if (samples[j] > best.value) best = {samples[j], theta0 + step * static_cast<double>(j)};
  if (n < 3) return best;
  for (std::size_t i = 0; i < searched; ++i) {
    const double centre = theta0 + step * static_cast<double>(brackets[i]);
    const auto [at, v] = goldenSectionMaximum(f, centre - step, centre + step, kAngleTolerance).best();
    if (v > best.value) best = {v, foldIntoTurn(at, theta0)};
  }
  return best;
}

}  // namespace linkwright::kinematics
