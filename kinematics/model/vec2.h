#pragma once
// The two planar vector operations the solver, the dynamics and the analyses all need.

#include <Eigen/Core>

namespace linkwright::kinematics {

/// z of the 3-D cross product a × b: positive when b is counter-clockwise of a.
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

/// v turned 90° counter-clockwise: ω × r for a rotation about z is ω·perp(r).
inline Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

}  // namespace linkwright::kinematics
