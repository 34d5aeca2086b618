#pragma once
// A number carried with its motion and its sensitivity to one dimension: the truncated Taylor
// series of x(t, p) about (t, p) = (0, p0) in the time t to second order and in one dimension
// p to first,
//
//   x = x₀ + x₁·t + x₂·t² + (d₀ + d₁·t + d₂·t²)·δp,   t³ = δp² = 0,
//
// so x₀ is the value, x₁ = ẋ, 2x₂ = ẍ, and d₀ = ∂x/∂p, d₁ = ∂ẋ/∂p, 2d₂ = ∂ẍ/∂p. Evaluating a
// position formula in this arithmetic, with the driver's input q(t) = q + q̇t + q̈t²/2 and the
// dimension p + δp, gives the position, velocity and acceleration and their exact derivatives
// with respect to p (forward-mode automatic differentiation: each operation is the chain
// rule, nothing is differenced). A function f of a jet a is its Taylor polynomial about a₀,
//
//   f(a) = f(a₀) + f′(a₀)·h + f″(a₀)·h²/2 + f‴(a₀)·h³/6,   h = a − a₀,
//
// exact here because h has no constant term, so h⁴ = 0 (its highest surviving power, t²δp,
// needs h³). Eigen's AutoDiffScalar gives first derivatives per level of nesting: the rates'
// sensitivities would need three nested levels of dynamic vectors; this fixed six-number
// series is the same arithmetic with no allocation.

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace linkwright::kinematics {

class MotionJet {
public:
  MotionJet() = default;
  /// A constant.
  explicit MotionJet(double value) { m_c[0] = value; }
  /// A dimension: its value, and 1 (or `perUnit`) as its derivative with respect to p.
  static MotionJet dimension(double value, double perUnit) {
    MotionJet j(value);
    j.m_c[3] = perUnit;
    return j;
  }
  /// The driver's input q with rate q̇ and acceleration q̈ at t = 0.
  static MotionJet motion(double position, double velocity, double acceleration) {
    MotionJet j(position);
    j.m_c[1] = velocity;
    j.m_c[2] = 0.5 * acceleration;
    return j;
  }

  /// From its coefficients, in the order of `coefficients()`.
  static MotionJet fromCoefficients(const std::array<double, 6>& c) {
    MotionJet j;
    j.m_c = c;
    return j;
  }
  /// The series' coefficients: of 1, t, t², δp, t·δp, t²·δp.
  const std::array<double, 6>& coefficients() const { return m_c; }

  double value() const { return m_c[0]; }
  double rate() const { return m_c[1]; }                           ///< ẋ
  double acceleration() const { return 2.0 * m_c[2]; }             ///< ẍ
  double valueSensitivity() const { return m_c[3]; }               ///< ∂x/∂p
  double rateSensitivity() const { return m_c[4]; }                ///< ∂ẋ/∂p
  double accelerationSensitivity() const { return 2.0 * m_c[5]; }  ///< ∂ẍ/∂p

  friend MotionJet operator+(MotionJet a, const MotionJet& b) {
    for (int i = 0; i < 6; ++i) a.m_c[i] += b.m_c[i];
    return a;
  }
  friend MotionJet operator-(MotionJet a, const MotionJet& b) {
    for (int i = 0; i < 6; ++i) a.m_c[i] -= b.m_c[i];
    return a;
  }
  friend MotionJet operator-(MotionJet a) {
    for (double& c : a.m_c) c = -c;
    return a;
  }
  friend MotionJet operator*(double s, MotionJet a) {
    for (double& c : a.m_c) c *= s;
    return a;
  }
  friend MotionJet operator*(const MotionJet& a, double s) { return s * a; }
  // Coefficients: [0] 1, [1] t, [2] t², [3] δp, [4] t·δp, [5] t²·δp.
  friend MotionJet operator*(const MotionJet& a, const MotionJet& b) {
    const auto& x = a.m_c;
    const auto& y = b.m_c;
    MotionJet r;
    r.m_c[0] = x[0] * y[0];
    r.m_c[1] = x[0] * y[1] + x[1] * y[0];
    r.m_c[2] = x[0] * y[2] + x[1] * y[1] + x[2] * y[0];
    r.m_c[3] = x[0] * y[3] + x[3] * y[0];
    r.m_c[4] = x[0] * y[4] + x[1] * y[3] + x[3] * y[1] + x[4] * y[0];
    r.m_c[5] = x[0] * y[5] + x[1] * y[4] + x[2] * y[3] + x[3] * y[2] + x[4] * y[1] + x[5] * y[0];
    return r;
  }
  friend MotionJet operator/(const MotionJet& a, const MotionJet& b) { return a * reciprocal(b); }
  friend MotionJet operator/(const MotionJet& a, double s) { return (1.0 / s) * a; }
  MotionJet& operator+=(const MotionJet& b) { return *this = *this + b; }
  MotionJet& operator-=(const MotionJet& b) { return *this = *this - b; }

  /// f(a) from f and its first three derivatives at a₀.
  static MotionJet compose(const MotionJet& a, double f0, double f1, double f2, double f3) {
    MotionJet h = a;
    h.m_c[0] = 0.0;
    const MotionJet h2 = h * h;
    const MotionJet h3 = h2 * h;
    return MotionJet(f0) + f1 * h + (0.5 * f2) * h2 + (f3 / 6.0) * h3;
  }
  friend MotionJet reciprocal(const MotionJet& a) {
    const double r = 1.0 / a.m_c[0];
    return compose(a, r, -r * r, 2.0 * r * r * r, -6.0 * r * r * r * r);
  }
  friend MotionJet sqrt(const MotionJet& a) {
    const double s = std::sqrt(a.m_c[0]);
    return compose(a, s, 0.5 / s, -0.25 / (s * a.m_c[0]), 0.375 / (s * a.m_c[0] * a.m_c[0]));
  }
  friend MotionJet sin(const MotionJet& a) {
    const double s = std::sin(a.m_c[0]), c = std::cos(a.m_c[0]);
    return compose(a, s, c, -s, -c);
  }
  friend MotionJet cos(const MotionJet& a) {
    const double s = std::sin(a.m_c[0]), c = std::cos(a.m_c[0]);
    return compose(a, c, -s, -c, s);
  }
  friend MotionJet atan(const MotionJet& a) {
    const double u = a.m_c[0], q = 1.0 / (1.0 + u * u);
    return compose(a, std::atan(u), q, -2.0 * u * q * q, (6.0 * u * u - 2.0) * q * q * q);
  }
  /// The direction of (x, y): atan2 of the values, its series from the turn relative to them
  /// (the vector rotated back by that angle lies near +x, where atan is smooth).
  friend MotionJet atan2(const MotionJet& y, const MotionJet& x) {
    const double angle = std::atan2(y.m_c[0], x.m_c[0]);
    const double c = std::cos(angle), s = std::sin(angle);
    const MotionJet along = c * x + s * y;
    const MotionJet across = c * y - s * x;
    MotionJet turn = atan(across / along);
    turn.m_c[0] = 0.0;
    return MotionJet(angle) + turn;
  }
  /// |a|, by the sign of its value (the derivatives of |x| where x ≠ 0).
  friend MotionJet abs(const MotionJet& a) { return a.m_c[0] < 0.0 ? -a : a; }

private:
  std::array<double, 6> m_c{};
};

/// A point's position as two jets.
struct JetVector {
  MotionJet x;
  MotionJet y;
  friend JetVector operator+(const JetVector& a, const JetVector& b) { return {a.x + b.x, a.y + b.y}; }
  friend JetVector operator-(const JetVector& a, const JetVector& b) { return {a.x - b.x, a.y - b.y}; }
  friend JetVector operator*(const MotionJet& s, const JetVector& v) { return {s * v.x, s * v.y}; }
  Eigen::Vector2d value() const { return {x.value(), y.value()}; }
};

inline MotionJet dot(const JetVector& a, const JetVector& b) { return a.x * b.x + a.y * b.y; }
inline MotionJet cross(const JetVector& a, const JetVector& b) { return a.x * b.y - a.y * b.x; }
inline JetVector perp(const JetVector& v) { return {-v.y, v.x}; }
inline MotionJet norm(const JetVector& v) { return sqrt(dot(v, v)); }

}  // namespace linkwright::kinematics
