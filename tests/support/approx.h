#pragma once
// Test helpers: Eigen-aware closeness with the failing component in the message, and the
// seeds' mechanisms solved at one crank angle.

#include "kinematics/model/fourbar.h"
#include "kinematics/solve/pose_solver.h"

#include <catch2/catch.hpp>

#include <Eigen/Core>

#include <sstream>
#include <string>

namespace linkwright::test {

/// Passes when |a − b| ≤ tolerance in both components; otherwise names both vectors.
inline bool near(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double tolerance, std::string* why = nullptr) {
  const bool ok = std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
  if (!ok && why != nullptr) {
    std::ostringstream s;
    s.precision(17);
    s << "(" << a.x() << ", " << a.y() << ") vs (" << b.x() << ", " << b.y() << "), tolerance " << tolerance;
    *why = s.str();
  }
  return ok;
}

/// Solves a four-bar at one crank state; fails the test if it does not assemble.
inline kinematics::Pose solveFourBar(const kinematics::FourBarLengths& lengths, kinematics::Branch branch,
                                     double crankAngle, double omega, double alpha = 0.0) {
  const auto mechanism = kinematics::makeFourBar(lengths, branch);
  REQUIRE(mechanism.ok());
  const auto pose = kinematics::solvePose(*mechanism, {crankAngle, omega, alpha});
  INFO((pose.ok() ? std::string() : pose.error().message));
  REQUIRE(pose.ok());
  return *pose;
}

} // namespace linkwright::test
