// The two-link arm of seed 004: inverse kinematics along a straight line at 2 m/s, both
// elbows, rates checked against the seed's own formulas and against finite differences, and
// exact reports where a path leaves the workspace.

#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {
constexpr TwoLinkArm kSeedArm{0.3, 0.2};  // seed 004: r1 = OA = 0.3 m, r2 = AB = 0.2 m
const LinePath kSeedPath{{0.3, 0.0}, {0.0, 0.3}, 2.0};
}  // namespace

TEST_CASE("both elbow solutions put the links at their lengths and the tip on target", "[analysis][arm]") {
  for (const Eigen::Vector2d& tip :
       {Eigen::Vector2d(0.3, 0.1), Eigen::Vector2d(-0.2, 0.25), Eigen::Vector2d(0.05, -0.4)}) {
    CAPTURE(tip.x(), tip.y());
    const auto open = solveTwoLinkArm(kSeedArm, Branch::Open, tip);
    const auto crossed = solveTwoLinkArm(kSeedArm, Branch::Crossed, tip);
    REQUIRE(open.ok());
    REQUIRE(crossed.ok());
    for (const ArmState& s : {*open, *crossed}) {
      CHECK(s.elbow.norm() == Approx(0.3).epsilon(1e-14));
      CHECK((tip - s.elbow).norm() == Approx(0.2).epsilon(1e-13));
      const Eigen::Vector2d rebuilt = 0.3 * Eigen::Vector2d(std::cos(s.upperAngle), std::sin(s.upperAngle)) +
                                      0.2 * Eigen::Vector2d(std::cos(s.forearmAngle), std::sin(s.forearmAngle));
      CHECK((rebuilt - tip).norm() < 1e-14);
    }
    CHECK(cross(tip, open->elbow) > 0.0);  // open: elbow to the left of O→B
    CHECK(cross(tip, crossed->elbow) < 0.0);
  }
}

TEST_CASE("joint rates along the seed's line equal the seed's own velocity formulas", "[analysis][arm][published]") {
  // Seed 004's MATLAB: w1 = (XB cos θ2 + YB sin θ2) / (r1 sin(θ2 − θ1)),
  //                    w2 = (XB cos θ1 + YB sin θ1) / (r2 sin(θ1 − θ2)), with (XB, YB) = (−√2, √2).
  const auto path = followLine(kSeedArm, Branch::Open, kSeedPath, 101);
  REQUIRE(path.ok());
  CHECK(path->unreachable.empty());
  CHECK(path->samples.back().time == Approx(0.3 * std::sqrt(2.0) / 2.0));
  const double xb = -std::sqrt(2.0), yb = std::sqrt(2.0);
  for (const ArmSample& s : path->samples) {
    CAPTURE(s.time);
    REQUIRE(s.reachable);
    const double t1 = s.state.upperAngle, t2 = s.state.forearmAngle;
    CHECK(s.state.upperOmega ==
          Approx((xb * std::cos(t2) + yb * std::sin(t2)) / (0.3 * std::sin(t2 - t1))).epsilon(1e-12));
    CHECK(s.state.forearmOmega ==
          Approx((xb * std::cos(t1) + yb * std::sin(t1)) / (0.2 * std::sin(t1 - t2))).epsilon(1e-12));
  }
}

TEST_CASE("joint accelerations agree with finite differences of the rates along the path", "[analysis][arm]") {
  // The tip moves at constant velocity, so α is purely the geometry's: compare with central
  // differences of ω over 1e-6 s (truncation ~1e-12 s², round-off ~1e-10 relative).
  const Eigen::Vector2d v = (kSeedPath.to - kSeedPath.from).normalized() * 2.0;
  const double h = 1e-6;
  for (const double t : {0.02, 0.07, 0.12, 0.19}) {
    CAPTURE(t);
    const Eigen::Vector2d p = kSeedPath.from + v * t;
    const auto now = solveTwoLinkArm(kSeedArm, Branch::Crossed, p, v);
    const auto before = solveTwoLinkArm(kSeedArm, Branch::Crossed, p - v * h, v);
    const auto after = solveTwoLinkArm(kSeedArm, Branch::Crossed, p + v * h, v);
    REQUIRE((now.ok() && before.ok() && after.ok()));
    CHECK(now->upperAlpha == Approx((after->upperOmega - before->upperOmega) / (2 * h)).epsilon(1e-6));
    CHECK(now->forearmAlpha == Approx((after->forearmOmega - before->forearmOmega) / (2 * h)).epsilon(1e-6));
    CHECK(now->upperOmega ==
          Approx(std::remainder(after->upperAngle - before->upperAngle, 2 * kPi) / (2 * h)).epsilon(1e-6));
  }
}

TEST_CASE("a path that leaves the workspace is reported with the exact times", "[analysis][arm][errors]") {
  // Out along +x from 0.3 m to 0.7 m at 2 m/s: beyond r1 + r2 = 0.5 m from t = 0.1 s to the end.
  const auto path = followLine(kSeedArm, Branch::Open, {{0.3, 0.0}, {0.7, 0.0}, 2.0}, 41);
  REQUIRE(path.ok());
  REQUIRE(path->unreachable.size() == 1);
  CHECK(path->unreachable[0].first == Approx(0.1).epsilon(1e-14));
  CHECK(path->unreachable[0].second == Approx(0.2).epsilon(1e-14));
  CHECK(path->samples[5].reachable);  // t = 0.025 s, 0.35 m out
  CHECK_FALSE(path->samples[30].reachable);
  // Through the hole |p| < r1 − r2 = 0.1 m: from (−0.3, 0.05) to (0.3, 0.05).
  const auto hole = followLine(kSeedArm, Branch::Open, {{-0.3, 0.05}, {0.3, 0.05}, 1.0}, 61);
  REQUIRE(hole.ok());
  REQUIRE(hole->unreachable.size() == 1);
  const double half = std::sqrt(0.1 * 0.1 - 0.05 * 0.05);
  CHECK(hole->unreachable[0].first == Approx(0.3 - half).epsilon(1e-12));
  CHECK(hole->unreachable[0].second == Approx(0.3 + half).epsilon(1e-12));
}

TEST_CASE("arm errors name the field and the reason", "[analysis][arm][errors]") {
  const auto far = solveTwoLinkArm(kSeedArm, Branch::Open, {0.6, 0.0});
  REQUIRE_FALSE(far.ok());
  CHECK(far.error().code == ErrorCode::NotAssemblable);
  CHECK_THAT(far.error().message, Catch::Contains("outside the workspace 0.1 to 0.5"));
  const auto stretched = solveTwoLinkArm(kSeedArm, Branch::Open, {0.5, 0.0}, {0.0, 1.0});
  REQUIRE_FALSE(stretched.ok());
  CHECK(stretched.error().code == ErrorCode::Singular);
  const auto badLink = solveTwoLinkArm({0.3, -0.2}, Branch::Open, {0.3, 0.0});
  REQUIRE_FALSE(badLink.ok());
  CHECK(badLink.error().field == "forearm");
  const auto badSpeed = followLine(kSeedArm, Branch::Open, {{0.3, 0.0}, {0.0, 0.3}, 0.0}, 10);
  REQUIRE_FALSE(badSpeed.ok());
  CHECK_THAT(badSpeed.error().message, Catch::Contains("speed must be positive and finite (got 0)"));
}
