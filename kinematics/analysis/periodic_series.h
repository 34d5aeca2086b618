#pragma once
// A quantity over one turn of a crank, known at N equally spaced samples, as its trigonometric
// interpolant: the one periodic function of degree N/2 through the samples,
//
//   p(θ) = a₀ + Σ_{k=1}^{K} (a_k cos kφ + b_k sin kφ),   φ = θ − θ₀,
//
// its coefficients from the samples' discrete Fourier transform (Eigen's FFT; at an even N the
// Nyquist term a_{N/2} cos(Nφ/2) is the last). A linkage that turns fully at a constant speed
// has forces, torques and energies that are smooth and periodic in θ, and for such a function
// the interpolant, its mean (the trapezoidal rule on a periodic grid) and its integral converge
// faster than any power of 1/N: a turn's figures read off 360 samples this way are exact to
// round-off where the trapezoidal rule alone would be 1e-5 out and a sampled peak 1e-4. Where a
// function is not smooth the series converges slowly; the caller's error estimate, the same
// figure on every other sample (halfGrid), says so.
//
// Extremes are refined between samples: every sample above (below) both neighbours brackets a
// maximum (minimum) of the interpolant, found by golden-section search on p to 1e-10 rad, and
// the largest (smallest) is returned. Evaluation costs O(K), the coefficients below 1e-17 of
// the largest being dropped.

#include <functional>
#include <vector>

namespace linkwright::kinematics {

/// A refined extreme of a periodic function: its value and where (rad).
struct PeriodicPeak {
  double value = 0.0;
  double at = 0.0;  ///< rad, in [θ₀, θ₀ + 2π)
};

class PeriodicSeries {
public:
  /// The interpolant through `samples`, f at θ₀ + 2πj/N for j = 0 … N − 1 (one turn, the
  /// closing sample left out; N ≥ 1). Samples must be finite.
  PeriodicSeries(double theta0, std::vector<double> samples);

  double theta0() const { return m_theta0; }
  std::size_t size() const { return m_samples.size(); }
  const std::vector<double>& samples() const { return m_samples; }
  /// θ of sample j, θ₀ + 2πj/N.
  double sampleAngle(std::size_t j) const;

  /// The mean over the turn, a₀ (the trapezoidal rule on the samples).
  double mean() const { return m_a.front(); }
  /// p(θ), any θ (periodic).
  double value(double theta) const;
  /// ∫_{θ₀}^{θ} (p − a₀) dφ: the periodic part of p's integral, 0 at θ₀.
  double surplusIntegral(double theta) const;
  /// The series of surplusIntegral, sampled on the same grid (its own refined extremes).
  PeriodicSeries surplusSeries() const;

  /// The refined largest and smallest value of p over the turn.
  PeriodicPeak maximum() const;
  PeriodicPeak minimum() const;

  /// The series through every other sample (N/2 of them, from sample 0): the same figure read
  /// off it, against this one's, estimates this one's error (an upper estimate: a smooth
  /// function's error falls much faster than the halving). Itself when N is odd or below 4.
  PeriodicSeries halfGrid() const;

private:
  PeriodicSeries(double theta0, std::vector<double> samples, std::vector<double> a, std::vector<double> b);
  double m_theta0;
  std::vector<double> m_samples;
  std::vector<double> m_a;  // a₀ … a_K
  std::vector<double> m_b;  // b₀ = 0 … b_K
};

/// The refined largest value of `f`, a smooth periodic function of θ known at `samples` (f at
/// θ₀ + 2πj/N): golden-section search on `f` between the neighbours of every sample above both
/// of its own, to 1e-10 rad. For |F| of a vector series, where the maximum is not a series'.
PeriodicPeak refinePeriodicMaximum(const std::function<double(double)>& f, double theta0,
                                   const std::vector<double>& samples);

}  // namespace linkwright::kinematics
