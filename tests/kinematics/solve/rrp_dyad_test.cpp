// The closed-form RRP dyad: both candidates on the guide at the right distance, the assembly
// limit, and rates that satisfy the differentiated constraint.

#include "kinematics/solve/rrp_dyad.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("both RRP candidates lie on the guide at the rod's length from the pin", "[solve][rrp]") {
  const Eigen::Vector2d p1(3.0, 4.0);
  const Eigen::Vector2d q(-1.0, 1.0);
  const Eigen::Vector2d u = Eigen::Vector2d(2.0, 1.0).normalized();
  const RrpCandidates c = rrpCandidates(p1, 6.0, q, u);
  REQUIRE(c.failure == AssemblyFailure::None);
  CHECK(c.open > c.crossed);
  for (const double s : {c.open, c.crossed}) {
    CAPTURE(s);
    CHECK(((q + s * u) - p1).norm() == Approx(6.0).epsilon(1e-14));
  }
}

TEST_CASE("an RRP dyad whose pin is farther from the guide than the rod fails as too far", "[solve][rrp][errors]") {
  const RrpCandidates c = rrpCandidates({0.0, 5.0}, 4.0, {0.0, 0.0}, {1.0, 0.0});
  CHECK(c.failure == AssemblyFailure::TooFar);
  const RrpCandidates touching = rrpCandidates({0.0, 4.0}, 4.0, {0.0, 0.0}, {1.0, 0.0});
  REQUIRE(touching.failure == AssemblyFailure::None);
  CHECK(touching.open == touching.crossed);  // one position: the rod stands across the guide
  CHECK(touching.reachGap == 0.0);
}

TEST_CASE("the slider rate satisfies (C - P1)·(vC - v1) = 0 and is refused at the toggle", "[solve][rrp]") {
  const Eigen::Vector2d u(1.0, 0.0);
  const Eigen::Vector2d r(3.0, -4.0);  // C − P1
  const Eigen::Vector2d v1(2.0, 5.0);
  double sDot = 0.0;
  REQUIRE(rrpSolveRate(r, u, r.dot(v1), sDot));
  CHECK(r.dot(sDot * u - v1) == Approx(0.0).margin(1e-12));
  double untouched = 7.0;
  CHECK_FALSE(rrpSolveRate({0.0, -4.0}, u, 1.0, untouched));
  CHECK(untouched == 7.0);
}
