#include "kinematics/solve/rrr_dyad.h"

#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
double rrrSine(const Eigen::Vector2d& c, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2) {
  const Eigen::Vector2d r1 = c - p1;
  const Eigen::Vector2d r2 = c - p2;
  const double scale = r1.norm() * r2.norm();
  return scale > 0.0 ? std::abs(cross(r1, r2)) / scale : 0.0;
}

bool rrrSolveRates(const Eigen::Vector2d& r1, const Eigen::Vector2d& r2, const Eigen::Vector2d& rhs,
                   Eigen::Vector2d& x) {
  double inverse = 0.0;
  if (!rrrInverseDeterminant(r1, r2, r1.norm() * r2.norm(), inverse)) return false;
  x = rrrSolve(r1, r2, inverse, rhs);
  return true;
}

}  // namespace linkwright::kinematics
