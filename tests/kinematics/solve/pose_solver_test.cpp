// Tests kinematics/solve/pose_solver.h: positions against the law of cosines, rates against
// the thesis's closed-form loop equations (with the α4 typo fixed), the request flags, the
// branch convention and guide, points on the coupler, and the failure reports.

#include "kinematics/solve/pose_solver.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/solve_scope.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::near;
using linkwright::test::solveFourBar;
using linkwright::test::within;

namespace {
constexpr auto kCrank = fourbar::kCrank.index;
constexpr auto kCoupler = fourbar::kCoupler.index;
constexpr auto kRocker = fourbar::kRocker.index;
constexpr auto kB = fourbar::kB.index;
constexpr auto kC = fourbar::kC.index;
}  // namespace

TEST_CASE("solvePose places the thesis four-bar at 90° by the law of cosines", "[pose_solver]") {
  const Pose pose = solveFourBar(kThesis, Branch::Open, degToRad(90.0), 1.0);
  // B = (0, 25), so BD = 65 and the triangles B–C–O4 have cosines 3/13 at O4, 71/91 at B, 3/7 at C.
  const double towardB = std::atan2(25.0, -60.0);
  const double towardO4 = std::atan2(-25.0, 60.0);
  // Values of order 100° from a few roundings: 1e-13 rad.
  CHECK(pose.linkAngle[kCrank] == within(kPi / 2.0, 1e-13));
  CHECK(pose.linkAngle[kRocker] == within(towardB - std::acos(3.0 / 13.0), 1e-13));
  CHECK(pose.linkAngle[kCoupler] == within(towardO4 + std::acos(71.0 / 91.0), 1e-13));
  CHECK(pose.transmissionAngle[kC] == within(std::acos(3.0 / 7.0), 1e-13));
  CHECK(pose.branchSign[kC] == 1);
  CHECK(pose.branchSign[kB] == 0);
  std::string why;
  CHECK(near(pose.position[kB], {0.0, 25.0}, 1e-13, &why));
  const Eigen::Vector2d c = Eigen::Vector2d(60.0, 0.0) + 45.0 * Eigen::Vector2d(std::cos(pose.linkAngle[kRocker]),
                                                                                std::sin(pose.linkAngle[kRocker]));
  CHECK(near(pose.position[kC], c, 1e-12, &why));
  INFO(why);
}

TEST_CASE("solvePose rates match the closed-form loop equations", "[pose_solver]") {
  const double a = kThesis.crank, b = kThesis.coupler, c = kThesis.rocker;
  const auto [angleDeg, omega2, alpha2] = GENERATE(table<double, double, double>(
      {{0.0, 1.0, 0.0}, {45.0, -2.5, 3.0}, {135.0, 10.0, -40.0}, {250.0, 0.3, 0.7}, {330.0, -1.0, -1.0}}));
  CAPTURE(angleDeg, omega2, alpha2);
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const Pose p = solveFourBar(kThesis, branch, degToRad(angleDeg), omega2, alpha2);
    const double t2 = p.linkAngle[kCrank], t3 = p.linkAngle[kCoupler], t4 = p.linkAngle[kRocker];
    const double w3 = p.linkOmega[kCoupler], w4 = p.linkOmega[kRocker];
    const double s = std::sin(t4 - t3);
    // Thesis eqs. (14) and (25), the α4 term as it should read: ω4²·L4·cos(θ4 − θ3).
    const double w3Formula = -omega2 * a * std::sin(t4 - t2) / (b * s);
    const double w4Formula = -omega2 * a * std::sin(t3 - t2) / (c * s);
    const double a3Formula = (alpha2 * a * std::sin(t2 - t4) + omega2 * omega2 * a * std::cos(t2 - t4) - w4 * w4 * c +
                              w3 * w3 * b * std::cos(t4 - t3)) /
                             (b * s);
    const double a4Formula = (alpha2 * a * std::sin(t2 - t3) + omega2 * omega2 * a * std::cos(t2 - t3) + w3 * w3 * b -
                              w4 * w4 * c * std::cos(t4 - t3)) /
                             (c * s);
    // Both sides are a few roundings of O(1)–O(100) terms over sin γ ≥ 0.4: 1e-12 relative to
    // the largest term's scale ω2²·a/(c·sin γ).
    const double scale = (std::abs(omega2) + omega2 * omega2 + std::abs(alpha2)) * a / (std::min(b, c) * std::abs(s));
    CHECK(p.linkOmega[kCrank] == omega2);
    CHECK(p.linkAlpha[kCrank] == within(alpha2, 1e-14 * (std::abs(alpha2) + 1.0)));
    CHECK(w3 == within(w3Formula, 1e-12 * scale));
    CHECK(w4 == within(w4Formula, 1e-12 * scale));
    CHECK(p.linkAlpha[kCoupler] == within(a3Formula, 1e-12 * scale));
    CHECK(p.linkAlpha[kRocker] == within(a4Formula, 1e-12 * scale));
    // Velocity of C two ways: along the rocker and via the coupler.
    const Eigen::Vector2d rc = p.position[kC] - Eigen::Vector2d(kThesis.frame, 0.0);
    const Eigen::Vector2d viaRocker = w4 * Eigen::Vector2d(-rc.y(), rc.x());
    std::string why;
    CHECK(near(p.velocity[kC], viaRocker, 1e-12 * scale * c, &why));
    INFO(why);
  }
}

TEST_CASE("solvePose: Crossed is the mirror image of Open", "[pose_solver]") {
  for (const double deg : {0.0, 30.0, 100.0, 200.0, 310.0}) {
    CAPTURE(deg);
    // With α2 = 0 the mirror motion (θ → −θ, ω2 → −ω2) has the same rates up to sign.
    const Pose open = solveFourBar(kThesis, Branch::Open, degToRad(deg), 1.5);
    const Pose crossed = solveFourBar(kThesis, Branch::Crossed, degToRad(-deg), 1.5);
    CHECK(std::sin(open.linkAngle[kRocker] - open.linkAngle[kCoupler]) > 0.0);
    CHECK(std::sin(crossed.linkAngle[kRocker] - crossed.linkAngle[kCoupler]) < 0.0);
    CHECK(crossed.branchSign[kC] == -1);
    for (std::size_t k = 0; k < 3; ++k) {
      CAPTURE(k);
      // Mirror about the frame line: angles negate, ω keeps (mirror and crank reversal both
      // flip it), α negates (ω2² does not flip).
      CHECK(linkwright::test::angleDifference(crossed.linkAngle[k], -open.linkAngle[k]) == within(0.0, 1e-13));
      CHECK(crossed.linkOmega[k] == within(open.linkOmega[k], 1e-12));
      CHECK(crossed.linkAlpha[k] == within(-open.linkAlpha[k], 1e-12));
    }
  }
}

TEST_CASE("solvePose computes only what the request asks for", "[pose_solver]") {
  const auto m = makeFourBar(kThesis, Branch::Open);
  REQUIRE(m.ok());
  const DriverState state{degToRad(60.0), 2.0, 1.0};
  const auto positions = solvePose(*m, state, {false, false});
  const auto velocities = solvePose(*m, state, {true, false});
  const auto implied = solvePose(*m, state, {false, true});
  const auto all = solvePose(*m, state);
  REQUIRE((positions.ok() && velocities.ok() && implied.ok() && all.ok()));
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(positions->position[i] == all->position[i]);
    CHECK(positions->velocity[i] == Eigen::Vector2d::Zero());
    CHECK(velocities->velocity[i] == all->velocity[i]);
    CHECK(velocities->acceleration[i] == Eigen::Vector2d::Zero());
    CHECK(implied->velocity[i] == all->velocity[i]);  // accelerations imply velocities
    CHECK(implied->acceleration[i] == all->acceleration[i]);
  }
  CHECK(positions->linkOmega == std::vector<double>(3, 0.0));
  CHECK(velocities->linkAlpha == std::vector<double>(3, 0.0));
  CHECK(all->linkOmega[kRocker] != 0.0);
  CHECK(all->linkAlpha[kRocker] != 0.0);
}

TEST_CASE("solvePose moves a coupler point rigidly with the coupler", "[pose_solver]") {
  const double along = 35.0, across = 20.0;
  const auto m = makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{along, across});
  REQUIRE(m.ok());
  const auto p = solvePose(*m, {degToRad(75.0), 3.0, -2.0});
  REQUIRE(p.ok());
  const double t3 = p->linkAngle[kCoupler], w3 = p->linkOmega[kCoupler], a3 = p->linkAlpha[kCoupler];
  const Eigen::Vector2d r =
      along * Eigen::Vector2d(std::cos(t3), std::sin(t3)) + across * Eigen::Vector2d(-std::sin(t3), std::cos(t3));
  const Eigen::Vector2d perp(-r.y(), r.x());
  const std::size_t iP = fourbar::kCouplerPoint.index;
  std::string why;
  // Magnitudes up to ~1e3 mm/s²: 1e-11.
  CHECK(near(p->position[iP], p->position[kB] + r, 1e-12, &why));
  CHECK(near(p->velocity[iP], p->velocity[kB] + w3 * perp, 1e-11, &why));
  CHECK(near(p->acceleration[iP], p->acceleration[kB] + a3 * perp - w3 * w3 * r, 1e-11, &why));
  INFO(why);
  CHECK((p->position[iP] - p->position[kC]).norm() == within(std::hypot(along - kThesis.coupler, across), 1e-12));
}

TEST_CASE("solvePoseInto follows a branch guide", "[pose_solver]") {
  const auto m = makeFourBar(kThesis, Branch::Open);
  REQUIRE(m.ok());
  Pose pose;
  preparePose(*m, pose);
  CHECK(pose.position.size() == 4);
  CHECK(pose.linkAngle.size() == 3);
  const DriverState state{degToRad(40.0), 1.0, 0.0};
  const std::vector<signed char> crossed{0, 0, 0, -1};
  REQUIRE(solvePoseInto(*m, state, {}, pose, {crossed, {}}).status == PoseStatus::Ok);
  CHECK(pose.branchSign[kC] == -1);
  const Pose reference = solveFourBar(kThesis, Branch::Crossed, state.position, 1.0);
  CHECK(pose.position[kC] == reference.position[kC]);

  // A predicted position picks the nearer candidate, whatever the signs say.
  const Pose open = solveFourBar(kThesis, Branch::Open, state.position, 1.0);
  std::vector<Eigen::Vector2d> predicted(4, Eigen::Vector2d::Zero());
  predicted[kC] = open.position[kC] + Eigen::Vector2d(0.5, -0.5);
  REQUIRE(solvePoseInto(*m, state, {}, pose, {crossed, predicted}).status == PoseStatus::Ok);
  CHECK(pose.branchSign[kC] == 1);
  CHECK(pose.position[kC] == open.position[kC]);
}

TEST_CASE("solvePose explains a pose that cannot be assembled", "[pose_solver][errors]") {
  SECTION("too far: a triple-rocker at 180°") {
    const auto m = makeFourBar({60.0, 50.0, 35.0, 40.0}, Branch::Open);
    REQUIRE(m.ok());
    const auto p = solvePose(*m, {kPi, 1.0, 0.0});
    REQUIRE_FALSE(p.ok());
    CHECK(p.error().code == ErrorCode::NotAssemblable);
    CHECK(p.error().field == "C");
    CHECK(p.error().message ==
          "C cannot be assembled at crank angle 180°: B and O4 are 110 mm apart, "
          "more than coupler + rocker = 75 mm");
  }
  SECTION("too close: a triple-rocker at 0°") {
    const auto m = makeFourBar({50.0, 40.0, 80.0, 20.0}, Branch::Crossed, "in");
    REQUIRE(m.ok());
    const auto p = solvePose(*m, {0.0, 1.0, 0.0}, {false, false});
    REQUIRE_FALSE(p.ok());
    CHECK(p.error().code == ErrorCode::NotAssemblable);
    CHECK(p.error().field == "C");
    CHECK(p.error().message ==
          "C cannot be assembled at crank angle 0°: B and O4 are 10 in apart, "
          "less than |coupler − rocker| = 60 in");
  }
  SECTION("the report names the culprit and the reason") {
    const auto m = makeFourBar({60.0, 50.0, 35.0, 40.0}, Branch::Open);
    REQUIRE(m.ok());
    Pose pose;
    preparePose(*m, pose);
    const PoseReport r = solvePoseInto(*m, {kPi, 0.0, 0.0}, {}, pose);
    CHECK(r.status == PoseStatus::NotAssemblable);
    CHECK(r.culprit == fourbar::kC);
    CHECK(r.failure == AssemblyFailure::TooFar);
  }
}

TEST_CASE("solvePose flags a toggle position as singular", "[pose_solver][errors]") {
  // Parallelogram at θ = 0: B = (25, 0) exactly, so B, C and O4 are exactly collinear.
  const auto m = makeFourBar({60.0, 25.0, 60.0, 25.0}, Branch::Open);
  REQUIRE(m.ok());
  const auto p = solvePose(*m, {0.0, 1.0, 0.0});
  REQUIRE_FALSE(p.ok());
  CHECK(p.error().code == ErrorCode::Singular);
  CHECK(p.error().field == "C");
  CHECK(p.error().message ==
        "C is at a toggle position at crank angle 0°: coupler and rocker are collinear, "
        "so angular velocity and acceleration are undefined there");
  // The position exists: a positions-only request succeeds there.
  const auto positions = solvePose(*m, {0.0, 1.0, 0.0}, {false, false});
  REQUIRE(positions.ok());
  CHECK(positions->position[kC] == Eigen::Vector2d(85.0, 0.0));
  Pose pose;
  preparePose(*m, pose);
  const PoseReport r = solvePoseInto(*m, {0.0, 1.0, 0.0}, {}, pose);
  CHECK(r.status == PoseStatus::Singular);
  CHECK(r.culprit == fourbar::kC);
  CHECK(pose.position[kC] == Eigen::Vector2d(85.0, 0.0));
}

TEST_CASE("solvePose rejects a non-finite driver state or an invalid mechanism", "[pose_solver][errors]") {
  const auto m = makeFourBar(kThesis, Branch::Open);
  REQUIRE(m.ok());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const auto angle = solvePose(*m, {nan, 1.0, 0.0});
  REQUIRE_FALSE(angle.ok());
  CHECK(angle.error() == Error{ErrorCode::InvalidValue, "input angle",
                               "input angle must be finite and within ±17453.3 rad (1e6 degrees) (got undefined)"});
  const auto omega = solvePose(*m, {0.0, inf, 0.0});
  REQUIRE_FALSE(omega.ok());
  CHECK(omega.error().field == "input omega");
  const auto alpha = solvePose(*m, {0.0, 1.0, -inf});
  REQUIRE_FALSE(alpha.ok());
  CHECK(alpha.error().message == "input alpha must be finite and within ±1e12 rad/s² (got undefined)");

  Mechanism broken = *m;
  broken.points[3].name = "B";
  const auto structure = solvePose(broken, {0.0, 1.0, 0.0});
  REQUIRE_FALSE(structure.ok());
  CHECK(structure.error().code == ErrorCode::InvalidStructure);
}

// solveBlockInto runs each step across the block before the next; the poses must come out
// exactly as solvePoseInto gives them one by one, whatever the linkage. A pose that fails ends
// the block: it is reported, and the poses after it are not solved further.
TEST_CASE("solveBlockInto gives solvePoseInto's numbers pose by pose", "[pose_solver]") {
  const auto fourBar = makeFourBar(kThesis, Branch::Open);
  const auto shaper = makeShaper(kSeedShaper);  // an RRP slider on a moving guide, points on links
  const auto sixBar = makeSixBar(kWattIISixBar);
  const auto tripleRocker = makeFourBar({60.0, 50.0, 35.0, 40.0}, Branch::Open);  // fails past ±85°
  REQUIRE((fourBar.ok() && shaper.ok() && sixBar.ok() && tripleRocker.ok()));
  for (const Mechanism* m : {&*fourBar, &*shaper, &*sixBar, &*tripleRocker}) {
    const SolveScope scope = scopeOf(*m, {});
    // From 20° in steps of 20°: the triple-rocker's fifth pose, at 100°, cannot be assembled.
    std::vector<DriverState> drivers;
    std::vector<Pose> block(kMaxBlock);
    std::vector<Pose*> poses;
    for (std::size_t b = 0; b < kMaxBlock; ++b) {
      drivers.push_back({degToRad(20.0 + 20.0 * static_cast<double>(b)), 1.5, -0.5});
      preparePose(*m, block[b]);
      poses.push_back(&block[b]);
    }
    std::vector<PoseReport> reports(kMaxBlock);
    const std::size_t solved = solveBlockInto(*m, drivers, {}, poses, {}, scope, reports);
    const std::size_t expectedSolved = m == &*tripleRocker ? 5 : kMaxBlock;
    REQUIRE(solved == expectedSolved);
    for (std::size_t b = 0; b < solved; ++b) {
      CAPTURE(b);
      Pose alone;
      preparePose(*m, alone);
      const PoseReport expected = solvePoseInto(*m, drivers[b], {}, alone);
      CHECK(reports[b] == expected);
      CHECK((expected.status == PoseStatus::NotAssemblable) == (b == 4 && m == &*tripleRocker));
      if (expected.status != PoseStatus::NotAssemblable) CHECK(block[b] == alone);
    }
  }
}
