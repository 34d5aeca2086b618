#pragma once
// A four-bar's coupler point P straight from the solver, for the coupler-curve tests: its curve
// over a full turn at `samples` crank angles (ω = 1, so v = dP/dθ), and P at one crank angle,
// on the open branch.

#include "kinematics/analysis/coupler_curve.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

namespace linkwright::test {

inline kinematics::CouplerCurve couplerCurveOf(const kinematics::FourBarLengths& l, kinematics::CouplerPointSpec p,
                                               std::size_t samples = 360) {
  namespace k = kinematics;
  const auto m = k::makeFourBar(l, k::Branch::Open, "mm", p);
  REQUIRE(m.ok());
  k::SweepSpec spec;
  spec.toAngle = 2.0 * k::kPi * static_cast<double>(samples - 1) / static_cast<double>(samples);
  spec.samples = samples;
  spec.omega = 1.0;
  const auto s = k::sweep(*m, spec);
  REQUIRE(s.ok());
  const std::size_t point = k::fourbar::kCouplerPoint.index;
  k::CouplerCurve c;
  for (std::size_t j = 0; j < s->size(); ++j) {
    REQUIRE(s->ok(j));
    c.parameter.push_back(s->inputAngle[j]);
    c.crankAngle.push_back(s->inputAngle[j]);
    c.point.push_back(s->position[point][j]);
    c.derivative.push_back(s->velocity[point][j]);
    c.rateOk.push_back(1);
  }
  return c;
}

inline Eigen::Vector2d couplerPointAt(const kinematics::FourBarLengths& l, kinematics::CouplerPointSpec p,
                                      double angle) {
  namespace k = kinematics;
  const auto m = k::makeFourBar(l, k::Branch::Open, "mm", p);
  REQUIRE(m.ok());
  const auto pose = k::solvePose(*m, {angle, 1.0, 0.0});
  REQUIRE(pose.ok());
  return pose->position[k::fourbar::kCouplerPoint.index];
}

}  // namespace linkwright::test
