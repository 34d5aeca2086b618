#include "kinematics/analysis/window_fits.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double distanceToSegment(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double s = l2 > 0.0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + s * ab - x).norm();
}

double angleBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(std::atan2(cross(a, b), a.dot(b)));
}

}  // namespace

WindowFits::WindowFits(const CouplerCurve& curve) : m_points(curve.point) {
  const std::size_t n = m_points.size();
  if (n == 0) return;
  Eigen::Vector2d lo = m_points.front(), hi = lo;
  for (const Eigen::Vector2d& p : m_points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  m_origin = 0.5 * (lo + hi);
  m_prefix.resize(2 * n + 1);
  m_length.resize(2 * n);
  m_length[0] = 0.0;
  for (std::size_t k = 0; k < 2 * n; ++k) {
    const Eigen::Vector2d p = m_points[k % n] - m_origin;
    const long double x = p.x(), y = p.y(), r = x * x + y * y;
    Moments m = m_prefix[k];
    m.n += 1;
    m.x += x;
    m.y += y;
    m.xx += x * x;
    m.xy += x * y;
    m.yy += y * y;
    m.xr += x * r;
    m.yr += y * r;
    m.r += r;
    m_prefix[k + 1] = m;
    if (k > 0) {
      const double step = (m_points[k % n] - m_points[(k - 1) % n]).norm();
      m_length[k] = m_length[k - 1] + step;
      if (k <= n) m_longestStep = std::max(m_longestStep, step);
    }
  }
  std::size_t nodes = 1;
  while (nodes < n) nodes *= 2;
  m_slack.assign(2 * nodes, 0.0);
  build(1, 0, n - 1);
}

void WindowFits::build(std::size_t node, std::size_t lo, std::size_t hi) {
  const Eigen::Vector2d &a = m_points[lo], &b = m_points[hi];
  double slack = 0.0;
  for (std::size_t k = lo + 1; k < hi; ++k) slack = std::max(slack, distanceToSegment(m_points[k], a, b));
  m_slack[node] = slack;
  if (lo == hi) return;
  const std::size_t mid = lo + (hi - lo) / 2;
  build(2 * node, lo, mid);
  build(2 * node + 1, mid + 1, hi);
}

WindowFits::Moments WindowFits::sum(SampleWindow w) const {
  const Moments &a = m_prefix[w.first], &b = m_prefix[w.last + 1];
  return {b.n - a.n, b.x - a.x, b.y - a.y, b.xx - a.xx, b.xy - a.xy, b.yy - a.yy, b.xr - a.xr, b.yr - a.yr, b.r - a.r};
}

WindowLine WindowFits::line(SampleWindow w) const {
  const Moments m = sum(w);
  const long double mx = m.x / m.n, my = m.y / m.n;
  const double sxx = static_cast<double>(m.xx - m.n * mx * mx), syy = static_cast<double>(m.yy - m.n * my * my);
  const double sxy = static_cast<double>(m.xy - m.n * mx * my);
  const double phi = 0.5 * std::atan2(2.0 * sxy, sxx - syy);  // the scatter's major axis
  return {m_origin + Eigen::Vector2d(static_cast<double>(mx), static_cast<double>(my)),
          Eigen::Vector2d(std::cos(phi), std::sin(phi))};
}

WindowCircle WindowFits::circle(SampleWindow w) const {
  const Moments m = sum(w);
  Eigen::Matrix3d normal;
  normal << static_cast<double>(m.xx), static_cast<double>(m.xy), static_cast<double>(m.x), static_cast<double>(m.xy),
      static_cast<double>(m.yy), static_cast<double>(m.y), static_cast<double>(m.x), static_cast<double>(m.y),
      static_cast<double>(m.n);
  const Eigen::Vector3d rhs(-static_cast<double>(m.xr), -static_cast<double>(m.yr), -static_cast<double>(m.r));
  const Eigen::Vector3d def = normal.ldlt().solve(rhs);
  const Eigen::Vector2d centre(-0.5 * def[0], -0.5 * def[1]);
  const double r2 = centre.squaredNorm() - def[2];
  if (!std::isfinite(r2) || r2 <= 0.0 || !centre.allFinite()) return {m_origin, 0.0, false};
  return {centre + m_origin, std::sqrt(r2), true};
}

template <class Dist, class ChordWorst>
bool WindowFits::within(std::size_t node, std::size_t lo, std::size_t hi, std::size_t qlo, std::size_t qhi,
                        const Dist& dist, const ChordWorst& chordWorst, double tol) const {
  if (hi < qlo || lo > qhi) return true;
  const std::size_t mid = lo + (hi - lo) / 2;
  if (qlo <= lo && hi <= qhi) {
    const Eigen::Vector2d &a = m_points[lo], &b = m_points[hi];
    if (!(dist(a) <= tol) || !(dist(b) <= tol)) return false;
    if (lo == hi || chordWorst(a, b) + m_slack[node] <= tol) return true;
  }
  return within(2 * node, lo, mid, qlo, qhi, dist, chordWorst, tol) &&
         within(2 * node + 1, mid + 1, hi, qlo, qhi, dist, chordWorst, tol);
}

template <class Dist, class ChordWorst>
bool WindowFits::windowWithin(SampleWindow w, const Dist& dist, const ChordWorst& chordWorst, double tol) const {
  const std::size_t n = m_points.size();
  if (w.last < n) return within(1, 0, n - 1, w.first, w.last, dist, chordWorst, tol);
  return within(1, 0, n - 1, w.first, n - 1, dist, chordWorst, tol) &&
         within(1, 0, n - 1, 0, w.last - n, dist, chordWorst, tol);
}

bool WindowFits::within(SampleWindow w, const WindowLine& line, double tol) const {
  const auto dist = [&](const Eigen::Vector2d& p) { return std::abs(cross(p - line.mean, line.direction)); };
  const auto chordWorst = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::max(dist(a), dist(b));
  };
  return windowWithin(w, dist, chordWorst, tol);
}

bool WindowFits::within(SampleWindow w, const WindowCircle& circle, double tol) const {
  const Eigen::Vector2d c = circle.centre;
  const double r = circle.radius;
  const auto dist = [&](const Eigen::Vector2d& p) { return std::abs((p - c).norm() - r); };
  const auto chordWorst = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const double nearest = distanceToSegment(c, a, b), farthest = std::max((a - c).norm(), (b - c).norm());
    return std::max(std::abs(nearest - r), std::abs(farthest - r));
  };
  return windowWithin(w, dist, chordWorst, tol);
}

double WindowFits::deviation(SampleWindow w, const WindowLine& line) const {
  double worst = 0.0;
  for (std::size_t k = w.first; k <= w.last; ++k)
    worst = std::max(worst, std::abs(cross(at(k) - line.mean, line.direction)));
  return worst;
}

double WindowFits::deviation(SampleWindow w, const WindowCircle& circle) const {
  double worst = 0.0;
  for (std::size_t k = w.first; k <= w.last; ++k)
    worst = std::max(worst, std::abs((at(k) - circle.centre).norm() - circle.radius));
  return worst;
}

double WindowFits::arcLength(SampleWindow w) const { return m_length[w.last] - m_length[w.first]; }

double WindowFits::turn(SampleWindow w, const Eigen::Vector2d& centre) const {
  double turn = 0.0;
  for (std::size_t k = w.first + 1; k <= w.last; ++k) turn += angleBetween(at(k - 1) - centre, at(k) - centre);
  return turn;
}

bool WindowFits::turnsAtLeast(SampleWindow w, const WindowCircle& circle, double tol, double least) const {
  // Every sample is at least ρ = r − tol from the centre, so a step of length d turns at most
  // 2 asin(d / 2ρ) ≤ (d / ρ) · asin(m) / m, m = the longest step / 2ρ (asin(x)/x grows with x).
  const double rho = circle.radius - tol;
  if (rho > 0.0) {
    const double m = m_longestStep / (2.0 * rho);
    if (m < 1.0) {
      const double factor = m > 0.0 ? std::asin(m) / m : 1.0;
      if (arcLength(w) / rho * factor * (1.0 + 1e-12) < least) return false;
    }
  }
  // The angle between two samples is at most the sum of the steps' between them.
  const std::size_t stride = std::max<std::size_t>(1, w.count() / 64);
  double lower = 0.0;
  std::size_t k = w.first;
  for (; k + stride <= w.last; k += stride)
    lower += angleBetween(at(k) - circle.centre, at(k + stride) - circle.centre);
  lower += angleBetween(at(k) - circle.centre, at(w.last) - circle.centre);
  if (lower >= least) return true;
  return turn(w, circle.centre) >= least;
}

}  // namespace linkwright::kinematics
