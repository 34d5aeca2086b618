// Instant centres checked against the pose solver's exact velocities, not against themselves:
// every point of link k moves as ω_k ẑ×(P − I1k), a centre shared by two links has one
// velocity from both, and the velocity ratio the centres give equals the solver's ω4/ω2 (or
// v/ω2 for a slider) over whole cycles of every Grashof class and of offset slider-cranks.
// Then the special poses: toggles, parallel lines, a flattened linkage, bad input.

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/analysis/limit_positions.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

// Velocity of point p of a link turning at omega about the finite centre `centre`.
Eigen::Vector2d spin(double omega, const InstantCentre& centre, const Eigen::Vector2d& p) {
  REQUIRE(centre.kind == CentreKind::Finite);
  return omega * perp(p - centre.position);
}

// The velocities compare to round-off of the velocity scale ω·length: the centres come from
// exact line intersections and the pose from closed-form rates, each good to ~1e-15 relative,
// and a grid angle is never within 1e-6 rad of a parallel pair, which would amplify it.
void checkVelocity(const Eigen::Vector2d& predicted, const Eigen::Vector2d& solved, double scale) {
  CAPTURE(predicted.x(), predicted.y(), solved.x(), solved.y());
  CHECK((predicted - solved).norm() <= 1e-9 * scale);
}

// Link k's velocity field: about its centre with the frame, or a translation if that is at
// infinity (then the link does not turn and the velocity is normal to the centre's direction).
void checkLinkMoves(double omega, const InstantCentre& centre, const Eigen::Vector2d& p, const Eigen::Vector2d& v,
                    double scale) {
  if (centre.kind == CentreKind::Finite) {
    checkVelocity(spin(omega, centre, p), v, scale);
  } else {
    REQUIRE(centre.kind == CentreKind::AtInfinity);
    CHECK(std::abs(omega) <= 1e-9 * scale);
    CHECK(std::abs(v.dot(centre.direction)) <= 1e-9 * scale);
  }
}

struct FourBarCase {
  FourBarLengths lengths;
  const char* grashof;
};

}  // namespace

TEST_CASE("four-bar centres reproduce the solver's velocities over the cycle", "[analysis][centres]") {
  // One linkage per Grashof class, on both branches; angles the linkage cannot reach are skipped.
  const auto [lengths, grashof] = GENERATE(values<FourBarCase>({
      {{60, 25, 70, 45}, "crank-rocker (thesis)"},
      {{20, 60, 70, 65}, "double-crank"},
      {{60, 50, 20, 45}, "double-rocker"},
      {{40, 30, 20, 25}, "triple-rocker"},
  }));
  const Branch branch = GENERATE(Branch::Open, Branch::Crossed);
  CAPTURE(grashof, branch == Branch::Open);
  const auto m = makeFourBar(lengths, branch, "mm", CouplerPointSpec{35.0, 20.0});
  REQUIRE(m.ok());
  const double omega2 = 1.7;
  int solved = 0;
  for (int deg = 0; deg < 360; deg += 7) {
    const auto pose = solvePose(*m, {degToRad(deg), omega2, 0.0});
    if (!pose) continue;
    ++solved;
    CAPTURE(deg);
    const auto c = instantCentres(*m, *pose);
    REQUIRE(c.ok());
    CHECK(c->ratio == RatioBodies{2, 4, false});
    const auto& pos = pose->position;
    const auto& vel = pose->velocity;
    const double w3 = pose->linkOmega[fourbar::kCoupler.index], w4 = pose->linkOmega[fourbar::kRocker.index];
    const double scale = std::abs(omega2) * c->scale;
    CHECK(c->centre(1, 2).position == pos[fourbar::kO2.index]);
    CHECK(c->centre(1, 4).position == pos[fourbar::kO4.index]);
    CHECK(c->centre(2, 3).position == pos[fourbar::kB.index]);
    CHECK(c->centre(3, 4).position == pos[fourbar::kC.index]);
    // Every point of the coupler (B, C and the coupler point P) turns about I13.
    for (const PointId p : {fourbar::kB, fourbar::kC, fourbar::kCouplerPoint})
      checkLinkMoves(w3, c->centre(1, 3), pos[p.index], vel[p.index], scale);
    // I24 is a point of the crank and of the rocker: one velocity from both.
    if (c->centre(2, 4).kind == CentreKind::Finite)
      checkVelocity(spin(omega2, c->centre(1, 2), c->centre(2, 4).position),
                    spin(w4, c->centre(1, 4), c->centre(2, 4).position), scale);
    // I23 = B on the crank, I34 = C on the rocker.
    checkVelocity(spin(omega2, c->centre(1, 2), c->centre(2, 3).position), vel[fourbar::kB.index], scale);
    checkVelocity(spin(w4, c->centre(1, 4), c->centre(3, 4).position), vel[fourbar::kC.index], scale);

    const MechanicalAdvantage ma = mechanicalAdvantage(*c);
    REQUIRE(ma.velocityRatio.kind == RatioKind::Finite);
    // 1e-9 relative, as asked; the margin covers a ratio that passes through zero, where
    // both sides are round-off (~1e-15) of a length over a length.
    CHECK(ma.velocityRatio.value == Approx(w4 / omega2).epsilon(1e-9).margin(1e-12));
    if (std::abs(w4 / omega2) > 1e-3) {  // away from the rocker's limits MA is well conditioned
      REQUIRE(ma.advantage.kind == RatioKind::Finite);
      CHECK(ma.advantage.value == Approx(omega2 / w4).epsilon(1e-9));
    }
  }
  CHECK(solved > 10);
}

TEST_CASE("slider-crank centres reproduce the solver's velocities, with offsets and both branches",
          "[analysis][centres]") {
  const double offset = GENERATE(0.0, 12.0, -20.0);
  const bool reversed = GENERATE(false, true);
  const Branch branch = GENERATE(Branch::Open, Branch::Crossed);
  CAPTURE(offset, reversed, branch == Branch::Open);
  const auto m = makeSliderCrank({30.0, 90.0, offset, reversed}, branch);
  REQUIRE(m.ok());
  const double omega2 = -2.3;
  const Eigen::Vector2d u = reversed ? Eigen::Vector2d(-1, 0) : Eigen::Vector2d(1, 0);
  for (int deg = 0; deg < 360; deg += 7) {
    CAPTURE(deg);
    const auto pose = solvePose(*m, {degToRad(deg), omega2, 0.0});
    REQUIRE(pose.ok());  // crank 30 < rod 90 − |offset|: the crank turns fully
    const auto c = instantCentres(*m, *pose);
    REQUIRE(c.ok());
    CHECK(c->ratio == RatioBodies{2, 4, true});
    CHECK((c->outputDirection - u).norm() < 1e-15);
    REQUIRE(c->centre(1, 4).kind == CentreKind::AtInfinity);
    CHECK(std::abs(c->centre(1, 4).direction.dot(u)) < 1e-15);  // normal to the guide
    const auto& pos = pose->position;
    const auto& vel = pose->velocity;
    const double w3 = pose->linkOmega[slidercrank::kRod.index];
    const double scale = std::abs(omega2) * c->scale;
    for (const PointId p : {slidercrank::kB, slidercrank::kC})
      checkLinkMoves(w3, c->centre(1, 3), pos[p.index], vel[p.index], scale);
    checkLinkMoves(0.0, c->centre(1, 4), pos[slidercrank::kC.index], vel[slidercrank::kC.index],
                   scale);  // the slider translates
    checkVelocity(spin(omega2, c->centre(1, 2), c->centre(2, 3).position), vel[slidercrank::kB.index], scale);
    // I24 on the crank moves with the slider, whose every point moves as C does.
    REQUIRE(c->centre(2, 4).kind == CentreKind::Finite);
    checkVelocity(spin(omega2, c->centre(1, 2), c->centre(2, 4).position), vel[slidercrank::kC.index], scale);

    const double v = vel[slidercrank::kC.index].dot(u);
    const MechanicalAdvantage ma = mechanicalAdvantage(*c);
    REQUIRE(ma.velocityRatio.kind == RatioKind::Finite);
    CHECK(ma.velocityRatio.value == Approx(v / omega2).epsilon(1e-9).margin(1e-12 * c->scale));
    if (std::abs(v / omega2) > 1e-3 * c->scale) {
      REQUIRE(ma.advantage.kind == RatioKind::Finite);
      CHECK(ma.advantage.value == Approx(omega2 / v).epsilon(1e-9));
    }
  }
}

TEST_CASE("at the rocker's limit positions the mechanical advantage is infinite", "[analysis][centres]") {
  // Crank and coupler in line: I24 = I12 and ω4 = 0 (limit_positions.h gives the exact angles).
  const FourBarLengths lengths{60, 25, 70, 45};
  const auto m = makeFourBar(lengths, Branch::Open);
  REQUIRE(m.ok());
  const LimitReport limits = fourBarLimitPositions(lengths, Branch::Open);
  REQUIRE(limits.positions.size() == 2);
  for (const LimitPosition& limit : limits.positions) {
    CAPTURE(radToDeg(limit.crankAngle), limit.extended);
    const auto pose = solvePose(*m, {limit.crankAngle, 1.0, 0.0});
    REQUIRE(pose.ok());
    CHECK(std::abs(pose->linkOmega[fourbar::kRocker.index]) < 1e-12);
    const auto c = instantCentres(*m, *pose);
    REQUIRE(c.ok());
    CHECK((c->centre(2, 4).position - c->centre(1, 2).position).norm() < 1e-9 * c->scale);
    const MechanicalAdvantage ma = mechanicalAdvantage(*c);
    CHECK(ma.advantage.kind == RatioKind::Infinite);
    CHECK(ma.velocityRatio == Ratio{RatioKind::Finite, 0.0});
  }
  // The slider's dead centres: crank and rod in line, crank angle asin(e / (r ± l)).
  const auto sc = makeSliderCrank({30.0, 90.0, 12.0, false});
  REQUIRE(sc.ok());
  for (const double angle : {std::asin(12.0 / 120.0), kPi + std::asin(12.0 / 60.0)}) {
    CAPTURE(radToDeg(angle));
    const auto pose = solvePose(*sc, {angle, 1.0, 0.0});
    REQUIRE(pose.ok());
    const auto c = instantCentres(*sc, *pose);
    REQUIRE(c.ok());
    CHECK(mechanicalAdvantage(*c).advantage.kind == RatioKind::Infinite);
  }
}

TEST_CASE("where the crank cannot drive, the velocity ratio is infinite and the advantage zero",
          "[analysis][centres]") {
  // Triple-rocker 40/30/20/25 at the end of its crank range: B, C, O4 in line, |BO4| = 45,
  // so cos θ = (30² + 40² − 45²) / (2·30·40). Positions only: the rates do not exist there.
  const auto m = makeFourBar({40, 30, 20, 25}, Branch::Open);
  REQUIRE(m.ok());
  const double angle = std::acos((900.0 + 1600.0 - 2025.0) / 2400.0);
  const auto pose = solvePose(*m, {angle, 0.0, 0.0}, SolveRequest{false, false});
  REQUIRE(pose.ok());
  const auto c = instantCentres(*m, *pose);
  REQUIRE(c.ok());
  const MechanicalAdvantage ma = mechanicalAdvantage(*c);
  CHECK(ma.velocityRatio.kind == RatioKind::Infinite);
  CHECK(ma.advantage == Ratio{RatioKind::Finite, 0.0});
  // A slider-crank with the rod normal to the guide: I24 at infinity.
  const auto sc = sliderCrankInstantCentres({0, 0}, {5, 10}, {5, 40}, {1, 0});
  REQUIRE(sc.ok());
  CHECK(sc->centre(2, 4).kind == CentreKind::AtInfinity);
  CHECK(sc->centre(2, 4).direction == Eigen::Vector2d(0, 1));
  CHECK(mechanicalAdvantage(*sc).velocityRatio.kind == RatioKind::Infinite);
  CHECK(mechanicalAdvantage(*sc).advantage == Ratio{RatioKind::Finite, 0.0});
}

TEST_CASE("parallel Kennedy lines put the centre at infinity, never NaN", "[analysis][centres]") {
  // A parallelogram: O2B ∥ O4C (I13 at infinity: the coupler translates) and BC ∥ O2O4 (I24 at
  // infinity: crank and rocker turn together, ratio exactly 1).
  for (const double deg : {30.0, 90.0, 137.0, 250.0}) {
    CAPTURE(deg);
    const Eigen::Vector2d b = 25.0 * Eigen::Vector2d(std::cos(degToRad(deg)), std::sin(degToRad(deg)));
    const auto c = fourBarInstantCentres({0, 0}, {60, 0}, b, b + Eigen::Vector2d(60, 0));
    REQUIRE(c.ok());
    REQUIRE(c->centre(1, 3).kind == CentreKind::AtInfinity);
    CHECK(std::abs(c->centre(1, 3).direction.x() * b.y() - c->centre(1, 3).direction.y() * b.x()) <
          1e-12 * b.norm());                      // along the crank
    CHECK(c->centre(1, 3).direction.x() >= 0.0);  // the canonical one of ±d
    CHECK(c->centre(1, 3).position == Eigen::Vector2d::Zero());
    REQUIRE(c->centre(2, 4).kind == CentreKind::AtInfinity);
    CHECK(c->centre(2, 4).direction == Eigen::Vector2d(1, 0));
    const MechanicalAdvantage ma = mechanicalAdvantage(*c);
    CHECK(ma.velocityRatio == Ratio{RatioKind::Finite, 1.0});
    CHECK(ma.advantage == Ratio{RatioKind::Finite, 1.0});
  }
  // Flattened: all four joints on the frame line, so both Kennedy pairs coincide.
  const auto flat = fourBarInstantCentres({0, 0}, {60, 0}, {25, 0}, {95, 0});
  REQUIRE(flat.ok());
  CHECK(flat->centre(1, 3).kind == CentreKind::Indeterminate);
  CHECK(flat->centre(2, 4).kind == CentreKind::Indeterminate);
  CHECK(mechanicalAdvantage(*flat).velocityRatio.kind == RatioKind::Undefined);
  CHECK(mechanicalAdvantage(*flat).advantage.kind == RatioKind::Undefined);
}

TEST_CASE("bad input gives an error naming the problem", "[analysis][centres][errors]") {
  const double nan = std::nan("");
  const auto notFinite = fourBarInstantCentres({0, 0}, {60, 0}, {nan, 0}, {40, 30});
  REQUIRE_FALSE(notFinite.ok());
  CHECK(notFinite.error().field == "B");
  CHECK(notFinite.error().message == "B has no finite position, so the instant centres cannot be found");
  // Joints beyond the input domain's ±1e9 are where a linkage within it may carry them.
  const auto far = fourBarInstantCentres({0, 0}, {1e9, 0}, {2e9, 0.5e9}, {1.8e9, 1.5e9});
  REQUIRE(far.ok());
  CHECK(far->centre(1, 3).kind == CentreKind::Finite);
  const auto coincident = fourBarInstantCentres({0, 0}, {60, 0}, {10, 10}, {10, 10});
  REQUIRE_FALSE(coincident.ok());
  CHECK(coincident.error().message == "coupler has coincident ends: its joints are at the same point");
  const auto noGuide = sliderCrankInstantCentres({0, 0}, {10, 0}, {50, 0}, {0, 0});
  REQUIRE_FALSE(noGuide.ok());
  CHECK(noGuide.error().field == "guide direction");

  const auto m = makeFourBar({60, 25, 70, 45}, Branch::Open);
  REQUIRE(m.ok());
  const auto wrongPose = instantCentres(*m, Pose{});
  REQUIRE_FALSE(wrongPose.ok());
  CHECK(wrongPose.error().message == "the pose has 0 points but the mechanism has 4");
}

TEST_CASE("a four-bar whose rocker carries a point has the same centres", "[analysis][centres]") {
  // The centres depend on the loop, not on where its links carry points.
  Mechanism plain = makeFourBar({60, 25, 70, 45}, Branch::Open).value();
  Mechanism carrying = plain;
  carrying.points.push_back({"R", AttachedPoint{fourbar::kRocker, 30.0, 5.0}});
  for (const double deg : {10.0, 130.0, 250.0}) {
    CAPTURE(deg);
    const auto a = instantCentres(plain, solvePose(plain, {degToRad(deg), 1.0, 0.0}).value());
    const auto b = instantCentres(carrying, solvePose(carrying, {degToRad(deg), 1.0, 0.0}).value());
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(*b == *a);
  }
}
