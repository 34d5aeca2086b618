#include "kinematics/solve/rrr_dyad.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

} // namespace

RrrCandidates rrrCandidates(const Eigen::Vector2d& p1, double l1, const Eigen::Vector2d& p2, double l2) {
  RrrCandidates out;
  const Eigen::Vector2d d = p2 - p1;
  const double L = d.norm();
  out.distance = L;
  const double slack = kAssemblyTolerance * (l1 + l2);
  if (L <= slack) {
    out.failure = AssemblyFailure::Coincident;
    return out;
  }
  // Heron's factors: each is a distance to one assembly limit, computed without cancellation.
  double reach = l1 + l2 - L;        // ≥ 0 unless too far
  double inner = L - std::abs(l1 - l2);  // ≥ 0 unless too close
  if (reach < -slack) {
    out.failure = AssemblyFailure::TooFar;
    return out;
  }
  if (inner < -slack) {
    out.failure = AssemblyFailure::TooClose;
    return out;
  }
  reach = std::max(reach, 0.0);
  inner = std::max(inner, 0.0);
  const double h = std::sqrt(reach * (l1 + l2 + L) * inner * (L + std::abs(l1 - l2))) / (2.0 * L);
  const double a = (l1 * l1 - l2 * l2 + L * L) / (2.0 * L);
  const Eigen::Vector2d u = d / L;
  const Eigen::Vector2d n(-u.y(), u.x());
  const Eigen::Vector2d foot = p1 + a * u;
  out.open = foot + h * n;
  out.crossed = foot - h * n;
  out.halfSeparation = h;
  return out;
}

double rrrSine(const Eigen::Vector2d& c, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
  const Eigen::Vector2d r1 = c - p1;
  const Eigen::Vector2d r2 = c - p2;
  const double scale = r1.norm() * r2.norm();
  return scale > 0.0 ? std::abs(cross(r1, r2)) / scale : 0.0;
}

bool rrrSolveRates(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, const Eigen::Vector2d& rhs,
                   Eigen::Vector2d& x) {
  return rrrSolveRates(r1, r2, rhs, x, r1.norm() * r2.norm());
}

bool rrrSolveRates(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, const Eigen::Vector2d& rhs,
                   Eigen::Vector2d& x, double scale) {
  const double det = cross(r1, r2);
  if (!(std::abs(det) > kSingularSine * scale)) return false;
  // Cramer's rule on [r1x r1y; r2x r2y] x = rhs.
  x = Eigen::Vector2d((rhs.x() * r2.y() - r1.y() * rhs.y()) / det,
                      (r1.x() * rhs.y() - rhs.x() * r2.x()) / det);
  return true;
}

} // namespace linkwright::kinematics
