// Tests kinematics/synthesis/motion_generation.h: the four-bar built from two or three coupler
// poses and two circle points, solved by the pose solver at the reported crank angles, puts
// the coupler point on every pose and turns the coupler by the poses' angles, to 1e-9 of the
// link lengths; the design is recognised as a four-bar with a tilted frame; defects and bad
// poses are reported; Norton's three-position Example 5-2 comes out to its printed link lengths,
// and his two-position Example 5-1, as an independent script solves it, to that script's digits.

#include "kinematics/synthesis/motion_generation.h"

#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"
#include "tests/support/catch.h"

#include <Eigen/Geometry>

#include <cmath>
#include <complex>
#include <tuple>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::within;

namespace {

// The poses reached by the design, checked with the solver.
void checkPassesThrough(const MotionSynthesis& s, const std::vector<CouplerPose>& poses) {
  const Mechanism& m = s.candidate.design.mechanism;
  const double scale = std::max({s.lengths.frame, s.lengths.crank, s.lengths.coupler, s.lengths.rocker});
  const auto first = solvePose(m, {s.crankAngles[0], 0.0, 0.0}, {false, false});
  REQUIRE(first.ok());
  for (std::size_t j = 0; j < poses.size(); ++j) {
    CAPTURE(j);
    const auto pose = solvePose(m, {s.crankAngles[j], 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    CHECK((pose->position[fourbar::kCouplerPoint.index] - poses[j].point).norm() < 1e-9 * scale);
    const double turned = pose->linkAngle[fourbar::kCoupler.index] - first->linkAngle[fourbar::kCoupler.index];
    CHECK(angleDifference(turned, poses[j].angle - poses[0].angle) == within(0.0, 1e-9));
  }
}

const std::vector<CouplerPose> kThree{
    {{0.0, 0.0}, 0.0}, {{40.0, 20.0}, degToRad(25.0)}, {{75.0, 15.0}, degToRad(55.0)}};

}  // namespace

TEST_CASE("Three poses: the linkage passes through each exactly", "[synthesis][motion]") {
  const auto [ax, ay, bx, by] = GENERATE(table<double, double, double, double>(
      {{-20.0, -30.0, 30.0, -40.0}, {-10.0, -25.0, 50.0, -20.0}, {0.0, -40.0, 40.0, -35.0}}));
  CAPTURE(ax, ay, bx, by);
  const auto s = synthesiseMotion3(kThree, {{ax, ay}, {bx, by}});
  REQUIRE(s.ok());
  // The centre points are equidistant from their circle point's three positions.
  for (std::size_t j = 1; j < 3; ++j) {
    CHECK((s->a[j] - s->o2).norm() == within(s->lengths.crank, 1e-10 * s->lengths.crank));
    CHECK((s->b[j] - s->o4).norm() == within(s->lengths.rocker, 1e-10 * s->lengths.rocker));
  }
  const auto fourBar = asFourBar(s->candidate.design.mechanism);
  REQUIRE(fourBar.has_value());
  CHECK(fourBar->lengths == s->lengths);
  CHECK(fourBar->frameAngle == within(std::atan2(s->o4.y() - s->o2.y(), s->o4.x() - s->o2.x()), 1e-15));
  REQUIRE_FALSE(s->candidate.has(DefectKind::Branch));
  checkPassesThrough(*s, kThree);
}

TEST_CASE("Two poses: any centre points on the bisectors pass through both", "[synthesis][motion]") {
  const std::vector<CouplerPose> poses{{{0.0, 0.0}, 0.0}, {{50.0, 10.0}, degToRad(40.0)}};
  for (const double along : {-30.0, 20.0, 60.0}) {
    CAPTURE(along);
    const auto s = synthesiseMotion2(poses, {{-10.0, -20.0}, {30.0, -25.0}}, along, -along / 2.0);
    REQUIRE(s.ok());
    CHECK((s->a[1] - s->o2).norm() == within(s->lengths.crank, 1e-10 * s->lengths.crank));
    CHECK((s->b[1] - s->o4).norm() == within(s->lengths.rocker, 1e-10 * s->lengths.rocker));
    if (!s->candidate.has(DefectKind::Branch)) {
      checkPassesThrough(*s, poses);
      continue;
    }
    // A branch defect is real: on the branch of pose 1 the solver misses pose 2.
    const auto pose = solvePose(s->candidate.design.mechanism, {s->crankAngles[1], 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    CHECK((pose->position[fourbar::kCouplerPoint.index] - poses[1].point).norm() > 1e-3);
  }
}

TEST_CASE("Motion candidates report their defects", "[synthesis][motion][defects]") {
  const auto s = synthesiseMotion3(kThree, {{-20.0, -30.0}, {30.0, -40.0}}, DefectBounds{}, {true, "mm"});
  REQUIRE(s.ok());
  for (const Defect& d : s->candidate.defects) CHECK_FALSE(d.message.empty());
  // The report agrees with the Grashof class.
  REQUIRE(s->candidate.grashof.has_value());
  CHECK(s->candidate.has(DefectKind::NotGrashof) == !s->candidate.grashof->inputFullyRotates);
}

TEST_CASE("Bad poses and circle points are errors naming the field", "[synthesis][motion][errors]") {
  const CirclePoints circle{{-20.0, -30.0}, {30.0, -40.0}};
  // Two identical poses.
  auto same = kThree;
  same[2] = same[1];
  auto r = synthesiseMotion3(same, circle);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().field == "poses[2]");
  // Pure translation along a line: every point's positions are collinear.
  const std::vector<CouplerPose> line{{{0.0, 0.0}, 0.3}, {{10.0, 5.0}, 0.3}, {{30.0, 15.0}, 0.3}};
  r = synthesiseMotion3(line, circle);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().field == "circlePoints.a");
  // Not three poses; a NaN.
  CHECK(synthesiseMotion3({kThree[0], kThree[1]}, circle).error().field == "poses");
  auto nan = kThree;
  nan[1].angle = NAN;
  CHECK(synthesiseMotion3(nan, circle).error().field == "poses[1].angle");
  CHECK(synthesiseMotion3(kThree, {{-20.0, -30.0}, {-20.0, -30.0}}).error().field == "circlePoints.b");
  // Two poses turned 90° about (10, 0): that point is the pole and cannot be a circle point.
  const std::vector<CouplerPose> turn{{{0.0, 0.0}, 0.0}, {{10.0, -10.0}, kPi / 2.0}};
  const auto pole = synthesiseMotion2(turn, {{10.0, 0.0}, {0.0, 5.0}}, 5.0, 5.0);
  REQUIRE_FALSE(pole.ok());
  CHECK(pole.error().field == "circlePoints.a");
}

TEST_CASE("Published example: two positions, Norton Example 5-1 (as solved in orxshi/fourbar)",
          "[synthesis][motion][published]") {
  // R. L. Norton, "Design of Machinery", sec. 5.4 (two-position motion generation by analytical
  // synthesis), Example 5-1, with its inputs as transcribed in github.com/orxshi/fourbar,
  // fourbar2/syn_two_pos_motion_gen.py: P21 = 2.416 at 165.2°, coupler rotation α2 = 43.3°;
  // free choices Z = 1.298 at 26.5°, S = 1.035 at 104.1° (the coupler point P seen from the
  // moving pivots A and B at pose 1), crank rotation β2 = 38.4°, rocker rotation γ2 = 85.6°.
  // The outputs are that repository's solution (fourbar2/RRR1_motion.py records it; the book's
  // printed answers were not in the corpora): a = 2.4669035392921197, b = 1.47616572201359,
  // c = 1.4856279407910054, d = 1.7007994988171315, frame O2O4 at 1.1066135686116216 rad,
  // crank at 0.14254149630753243 rad from the frame at pose 1. Both solutions are exact in the
  // same inputs, so the tolerance is round-off (1e-9).
  // Linkwright's free choices are the circle points and the centre points' places on their
  // bisectors. With P1 at the origin, A1 = −Z and B1 = −S; a crank that turns β carries A1 to
  // A2 about the point of the bisector at (|A1A2| / 2) / tan(β / 2) from the chord's midpoint,
  // to the left of A1→A2 for a positive turn.
  const double alpha2 = degToRad(43.3), beta2 = degToRad(38.4), gamma2 = degToRad(85.6);
  const Eigen::Vector2d z = 1.298 * Eigen::Vector2d(std::cos(degToRad(26.5)), std::sin(degToRad(26.5)));
  const Eigen::Vector2d sv = 1.035 * Eigen::Vector2d(std::cos(degToRad(104.1)), std::sin(degToRad(104.1)));
  const Eigen::Vector2d p2 = 2.416 * Eigen::Vector2d(std::cos(degToRad(165.2)), std::sin(degToRad(165.2)));
  const std::vector<CouplerPose> poses{{{0.0, 0.0}, degToRad(26.5)}, {p2, degToRad(26.5) + alpha2}};
  const Eigen::Rotation2Dd turn(alpha2);
  const auto along = [&](const Eigen::Vector2d& first, double rotation) {
    return 0.5 * (p2 + turn * first - first).norm() / std::tan(0.5 * rotation);
  };
  const auto s =
      synthesiseMotion2(poses, {-z, -sv}, along(-z, beta2), along(-sv, gamma2), DefectBounds{}, {false, "in"});
  REQUIRE(s.ok());
  CHECK(s->lengths.crank == within(2.4669035392921197, 1e-9));
  CHECK(s->lengths.coupler == within(1.47616572201359, 1e-9));
  CHECK(s->lengths.rocker == within(1.4856279407910054, 1e-9));
  CHECK(s->lengths.frame == within(1.7007994988171315, 1e-9));
  const auto fourBar = asFourBar(s->candidate.design.mechanism);
  REQUIRE(fourBar.has_value());
  CHECK(fourBar->frameAngle == within(1.1066135686116216, 1e-9));
  CHECK(angleDifference(s->crankAngles[0] - fourBar->frameAngle, 0.14254149630753243) == within(0.0, 1e-9));
  // Checked by the pose solver: P on both poses, the coupler turned α2, and the crank and the
  // rocker turned by the example's free choices β2 and γ2.
  checkPassesThrough(*s, poses);
  CHECK(angleDifference(s->crankAngles[1] - s->crankAngles[0], beta2) == within(0.0, 1e-12));
  const Mechanism& m = s->candidate.design.mechanism;
  const auto first = solvePose(m, {s->crankAngles[0], 0.0, 0.0}, {false, false});
  const auto second = solvePose(m, {s->crankAngles[1], 0.0, 0.0}, {false, false});
  REQUIRE(first.ok());
  REQUIRE(second.ok());
  const double rockerTurn = second->linkAngle[fourbar::kRocker.index] - first->linkAngle[fourbar::kRocker.index];
  CHECK(angleDifference(rockerTurn, gamma2) == within(0.0, 1e-9));
}

TEST_CASE("Published example: three positions, Norton Example 5-2", "[synthesis][motion][published]") {
  // R. L. Norton, "Design of Machinery" (McGraw-Hill, 2000), Example 5-2 (three-position
  // motion synthesis by the analytical method). Its data and printed link lengths, as quoted in
  // M. Samarth, "Kinematic synthesis and visualization of a flap actuation mechanism" (BITS
  // Pilani / CSIR-NAL report, 2025; github.com/shoutingfish123/aircraft-flap-mechanism-synthesis,
  // docs/ProjectReport.pdf, Fig. 2 and Table 1): P21 = 2.798 at -31.19 deg, P31 = 3.919 at
  // -16.34 deg, coupler rotations a2 = -45 deg, a3 = 9.3 deg; free choices: crank rotations
  // b2 = 342.3, b3 = 324.8 deg, rocker rotations g2 = 30.9, g3 = 80.6 deg; printed lengths:
  // crank W = 6.832, coupler V = 1.399, rocker U = 3.2 (the report's precision).
  const auto polar = [](double length, double deg) { return std::polar(length, degToRad(deg)); };
  const std::complex<double> p21 = polar(2.798, -31.19), p31 = polar(3.919, -16.34);
  const double a2 = degToRad(-45.0), a3 = degToRad(9.3);
  const double b2 = degToRad(342.3), b3 = degToRad(324.8), g2 = degToRad(30.9), g3 = degToRad(80.6);
  // The book's free choices are the rotations; Linkwright's are the circle points. Norton's
  // standard-form dyad equations (e^{i r_j} - 1) W + (e^{i a_j} - 1) Z = P_j1, j = 2, 3, give the
  // dyad's vector Z from its moving pivot to P, so the circle point at pose 1 is P1 - Z.
  const auto circlePoint = [&](double r2, double r3) {
    const std::complex<double> i{0.0, 1.0};
    const std::complex<double> m11 = std::exp(i * r2) - 1.0, m12 = std::exp(i * a2) - 1.0;
    const std::complex<double> m21 = std::exp(i * r3) - 1.0, m22 = std::exp(i * a3) - 1.0;
    const std::complex<double> z = (m11 * p31 - m21 * p21) / (m11 * m22 - m12 * m21);  // Cramer
    return Eigen::Vector2d(-z.real(), -z.imag());
  };
  const std::vector<CouplerPose> poses{
      {{0.0, 0.0}, 0.0}, {{p21.real(), p21.imag()}, a2}, {{p31.real(), p31.imag()}, a3}};
  const auto s = synthesiseMotion3(poses, {circlePoint(b2, b3), circlePoint(g2, g3)}, DefectBounds{}, {false, "in"});
  REQUIRE(s.ok());
  // Half a unit in the last printed digit.
  CHECK(s->lengths.crank == within(6.832, 0.0005));
  CHECK(s->lengths.coupler == within(1.399, 0.0005));
  CHECK(s->lengths.rocker == within(3.2, 0.05));
  // Checked by the pose solver: P on all three poses, the coupler turned a2 and a3, and the crank
  // and the rocker turned by the example's free choices.
  checkPassesThrough(*s, poses);
  const Mechanism& m = s->candidate.design.mechanism;
  const auto first = solvePose(m, {s->crankAngles[0], 0.0, 0.0}, {false, false});
  REQUIRE(first.ok());
  for (const auto& [j, beta, gamma] : {std::tuple{1, b2, g2}, std::tuple{2, b3, g3}}) {
    CAPTURE(j);
    const auto pose = solvePose(m, {s->crankAngles[j], 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    CHECK(angleDifference(s->crankAngles[j] - s->crankAngles[0], beta) == within(0.0, 1e-9));
    const double rockerTurn = pose->linkAngle[fourbar::kRocker.index] - first->linkAngle[fourbar::kRocker.index];
    CHECK(angleDifference(rockerTurn, gamma) == within(0.0, 1e-9));
  }
}
