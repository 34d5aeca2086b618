// Tests kinematics/explore/cognates.h: the construction's identities (the third pivot, P on each
// cognate's coupler, rigid links turning with the original's), each cognate's coupler point on
// the original's curve and the original's on each cognate's, both ways round, for the thesis
// four-bar with a coupler point, the Miranda example and 100 random Grashof four-bars, and the
// refusals, each as a sentence.

#include "kinematics/explore/cognates.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/kinematics/design/drawn_fourbar.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <random>
#include <tuple>

using namespace linkwright::kinematics;

namespace {

constexpr PointId kP{4};  // a cognate's P (makeFourBar's order)

double angleOf(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }
double turnBetween(double a, double b) { return std::remainder(b - a, 2.0 * kPi); }

// The thesis crank-rocker (seed 000) with P 35 mm along and 20 mm across its coupler.
Design thesisWithCouplerPoint() {
  return fourBarDesign(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
}

Design drawnDesign(const FourBarLengths& lengths, Branch branch, CouplerPointSpec p) {
  Design d;
  d.kind = "four-bar";
  d.mechanism = linkwright::test::drawnFourBar(lengths, branch, p).mechanism;
  return d;
}

// The original's joints at every sample of its design's grid (all assembled).
struct OriginalMotion {
  SweepResult sweep;
  FourBarStructure fourBar;
  PointId p;
  double size = 0.0;  ///< the largest link or coupler-point offset, length unit
  FourBarJoints at(std::size_t j) const {
    return {sweep.position[fourBar.o2.index][j], sweep.position[fourBar.o4.index][j],
            sweep.position[fourBar.b.index][j], sweep.position[fourBar.c.index][j], sweep.position[p.index][j]};
  }
};

OriginalMotion motionOf(const CognateSet& set, std::size_t samples = 1441) {
  const Design& d = set.original.design;
  OriginalMotion m;
  SweepSpec spec = designSweepSpec(d);
  spec.samples = samples;
  m.sweep = sweep(d.mechanism, spec).value();
  m.fourBar = set.original.fourBar;
  m.p = *d.mechanism.findPoint(set.couplerPoint);
  const FourBarLengths& l = m.fourBar.lengths;
  m.size = std::max({l.frame, l.crank, l.coupler, l.rocker, (m.at(0).p - m.at(0).b).norm()});
  return m;
}

// The distance from `target` to the coupler point of `design` at input `input` (rad), on the
// nearer of its two assembly branches (a cognate driven by a link that reverses passes from one
// to the other in the cycle; both together are its whole coupler curve).
double distanceToCurveAt(const Design& design, PointId p, double input, const Eigen::Vector2d& target) {
  const PointId c = asFourBar(design.mechanism)->c;
  SolveRequest positions;  // a cognate's toggle is on the curve too, though its rates are not defined there
  positions.velocities = positions.accelerations = false;
  double nearest = std::numeric_limits<double>::infinity();
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    Mechanism m = design.mechanism;
    std::get<RrrPoint>(m.points[c.index].definition).branch = branch;
    const auto pose = solvePose(m, DriverState{input, 0.0, 0.0}, positions);
    if (pose) nearest = std::min(nearest, (pose->position[p.index] - target).norm());
  }
  return nearest;
}

// Every check of a four-bar's cognates: the curves, both ways round.
void checkCognates(const CognateSet& set) {
  const OriginalMotion o = motionOf(set);
  const double tolerance = 1e-9 * o.size;
  const Design& first = set.cognates[0].design;
  const Design& second = set.cognates[1].design;
  REQUIRE(first.mechanism.points[4].name == "P");
  REQUIRE(second.mechanism.points[4].name == "P");
  const double coupler0 = o.sweep.linkAngle[1][0];

  // The original's curve on each cognate's: cognate 2 at the original's own input; cognate 1
  // at its input q0 + (θ3 − θ3 at q0), its crank turning with the original's coupler.
  double worst1 = 0.0, worst2 = 0.0;
  for (std::size_t j = 0; j < o.sweep.size(); ++j) {
    REQUIRE(o.sweep.assembled(j));
    const Eigen::Vector2d p = o.at(j).p;
    const double q = o.sweep.inputAngle[j];
    worst2 = std::max(worst2, distanceToCurveAt(second, kP, q, p));
    const double q1 = set.constructedAt + (o.sweep.linkAngle[1][j] - coupler0);
    worst1 = std::max(worst1, distanceToCurveAt(first, kP, q1, p));
  }
  CHECK(worst1 <= tolerance);
  CHECK(worst2 <= tolerance);

  // Cognate 2 swept over its own grid, on its own branch, is the original sample by sample.
  const SweepResult s2 = sweep(second.mechanism,
                               [&] {
                                 SweepSpec spec = designSweepSpec(second);
                                 spec.samples = o.sweep.size();
                                 return spec;
                               }())
                             .value();
  double worstColumn = 0.0;
  for (std::size_t j = 0; j < s2.size(); ++j) {
    REQUIRE(s2.assembled(j));
    worstColumn = std::max(worstColumn, (s2.position[4][j] - o.at(j).p).norm());
  }
  CHECK(worstColumn <= tolerance);

  // Each cognate's curve on the original's: cognate 1 swept over its own grid; the original's
  // input is its coupler's angle less the angle it had at the constructed pose.
  const SweepResult s1 = sweep(first.mechanism, designSweepSpec(first)).value();
  const Pose at0 = solvePose(first.mechanism, DriverState{set.constructedAt, 0.0, 0.0}).value();
  double worstBack = 0.0;
  for (std::size_t j = 0; j < s1.size(); ++j) {
    REQUIRE(s1.assembled(j));
    const double q = set.constructedAt + turnBetween(at0.linkAngle[1], s1.linkAngle[1][j]);
    worstBack = std::max(worstBack, distanceToCurveAt(set.original.design, o.p, q, s1.position[4][j]));
  }
  CHECK(worstBack <= tolerance);
}

}  // namespace

TEST_CASE("cognateJoints: O6 makes triangle O2 O4 O6 similar to B C P, and P rides on both cognates' couplers",
          "[cognates]") {
  const FourBarJoints j{{1.0, 2.0}, {61.0, 7.0}, {-10.0, 25.0}, {48.0, 60.0}, {20.0, 70.0}};
  const CognateJoints c = cognateJoints(j);
  // Similar triangles, by lengths and angles rather than complex products.
  const double scale = (j.p - j.b).norm() / (j.c - j.b).norm();
  CHECK((c.thirdPivot - j.o2).norm() == Approx(scale * (j.o4 - j.o2).norm()).epsilon(1e-14));
  CHECK(turnBetween(angleOf(j.o4 - j.o2), angleOf(c.thirdPivot - j.o2)) ==
        Approx(turnBetween(angleOf(j.c - j.b), angleOf(j.p - j.b))).epsilon(1e-14));
  // Parallelograms O2 B P B1 and O4 C P C2.
  CHECK((c.first.b - j.o2 - (j.p - j.b)).norm() < 1e-12);
  CHECK((c.second.c - j.o4 - (j.p - j.c)).norm() < 1e-12);
  // P on cognate 1's coupler at 1/z, on cognate 2's at z/(z − 1).
  const std::complex<double> z = couplerRatio(j);
  CHECK(std::abs(couplerRatio(c.first) - 1.0 / z) < 1e-13);
  CHECK(std::abs(couplerRatio(c.second) - z / (z - 1.0)) < 1e-13);
  // The cognates share the original's pivots and the third.
  CHECK(c.first.o2 == j.o2);
  CHECK(c.first.o4 == c.thirdPivot);
  CHECK(c.second.o2 == c.thirdPivot);
  CHECK(c.second.o4 == j.o4);
}

TEST_CASE("The constructed cognates are rigid and turn with the original's links at every sample", "[cognates]") {
  const CognateSet set = cognates(thesisWithCouplerPoint()).value();
  const OriginalMotion o = motionOf(set, 3601);
  const CognateJoints c0 = cognateJoints(o.at(0));
  const auto lengths = [](const FourBarJoints& j) {
    return std::array<double, 6>{(j.b - j.o2).norm(), (j.c - j.b).norm(), (j.c - j.o4).norm(),
                                 (j.p - j.b).norm(),  (j.p - j.c).norm(), (j.o4 - j.o2).norm()};
  };
  const auto l1 = lengths(c0.first), l2 = lengths(c0.second);
  // Cognate 1 is the original scaled by |z| with crank and coupler swapped; cognate 2 by |1 − z|
  // with coupler and rocker swapped.
  const double z = std::abs(set.z), w = std::abs(1.0 - set.z);
  const FourBarLengths& l = set.original.fourBar.lengths;
  CHECK(l1[0] == Approx(z * l.coupler).epsilon(1e-12));
  CHECK(l1[1] == Approx(z * l.crank).epsilon(1e-12));
  CHECK(l1[2] == Approx(z * l.rocker).epsilon(1e-12));
  CHECK(l2[0] == Approx(w * l.crank).epsilon(1e-12));
  CHECK(l2[1] == Approx(w * l.rocker).epsilon(1e-12));
  CHECK(l2[2] == Approx(w * l.coupler).epsilon(1e-12));
  // Each cognate link's angle less that of the original link it turns with (the derivation).
  const auto offsets = [](const FourBarJoints& a, const CognateJoints& c) {
    const double theta2 = angleOf(a.b - a.o2), theta3 = angleOf(a.c - a.b), theta4 = angleOf(a.c - a.o4);
    return std::array<double, 6>{
        turnBetween(theta3, angleOf(c.first.b - c.first.o2)),  turnBetween(theta2, angleOf(c.first.c - c.first.b)),
        turnBetween(theta4, angleOf(c.first.c - c.first.o4)),  turnBetween(theta2, angleOf(c.second.b - c.second.o2)),
        turnBetween(theta4, angleOf(c.second.c - c.second.b)), turnBetween(theta3, angleOf(c.second.c - c.second.o4))};
  };
  const auto turn0 = offsets(o.at(0), c0);
  double drift = 0.0, turn = 0.0;
  for (std::size_t j = 0; j < o.sweep.size(); ++j) {
    const CognateJoints c = cognateJoints(o.at(j));
    CHECK((c.thirdPivot - c0.thirdPivot).norm() < 1e-12 * o.size);
    const auto m1 = lengths(c.first), m2 = lengths(c.second);
    const auto t = offsets(o.at(j), c);
    for (std::size_t k = 0; k < 6; ++k) {
      drift = std::max({drift, std::abs(m1[k] - l1[k]), std::abs(m2[k] - l2[k])});
      turn = std::max(turn, std::abs(turnBetween(turn0[k], t[k])));
    }
  }
  CHECK(drift <= 1e-12 * o.size);
  CHECK(turn <= 1e-12);
}

TEST_CASE("The thesis four-bar's cognates trace its coupler curve, and it theirs", "[cognates]") {
  const CognateSet set = cognates(thesisWithCouplerPoint()).value();
  checkCognates(set);
  // Norton §3.9: a Grashof crank-rocker has one crank-rocker cognate and one double-rocker.
  CHECK(set.original.grashof.category == GrashofClass::CrankRocker);
  CHECK(set.cognates[0].grashof.category == GrashofClass::DoubleRocker);
  CHECK(set.cognates[1].grashof.category == GrashofClass::CrankRocker);
  // The original's worst transmission angle is the thesis's 25.21° (transmission_test.cpp).
  REQUIRE(set.original.worstTransmission.has_value());
  CHECK(radToDeg(*set.original.worstTransmission) == Approx(25.21).margin(0.005));
  // Cognate 2 is the original scaled, coupler and rocker swapped, its crank at the original's
  // angle from its frame line: μ is symmetric in coupler and rocker, so it is the original's.
  REQUIRE(set.cognates[1].worstTransmission.has_value());
  CHECK(*set.cognates[1].worstTransmission == Approx(*set.original.worstTransmission).epsilon(1e-12));
  // Cognate 1's crank turns back where its coupler and rocker fold: μ reaches 0 there, at the
  // edges of its assembly range, which its sampled swing falls short of by a little.
  REQUIRE(set.cognates[0].worstTransmission.has_value());
  CHECK(radToDeg(*set.cognates[0].worstTransmission) < 1e-5);
  // Speeds: cognate 2's crank turns at the original crank's ω, cognate 1's at the coupler's ω3.
  CHECK(set.cognates[1].turnsWith[0] == OriginalLink::Crank);
  CHECK(set.cognates[1].crankSpeedRatioMin == 1.0);
  CHECK(set.cognates[0].turnsWith[0] == OriginalLink::Coupler);
  REQUIRE(set.cognates[0].crankSpeedRatioMin.has_value());
  CHECK(*set.cognates[0].crankSpeedRatioMin < 0.0);
  CHECK(*set.cognates[0].crankSpeedRatioMax > 0.0);
  // Cognate 1's grid is the range its crank sweeps, within a turn; cognate 2's is the original's.
  CHECK(set.cognates[0].design.toDeg - set.cognates[0].design.fromDeg < 360.0);
  CHECK(set.cognates[1].design.fromDeg == set.original.design.fromDeg);
  CHECK(set.cognates[1].design.toDeg == set.original.design.toDeg);
}

TEST_CASE("The Miranda four-bar's cognates: P on the coupler line puts the three pivots on one line", "[cognates]") {
  const CognateSet set = cognates(designForExample("miranda-fourbar").value()).value();
  CHECK(set.z.imag() == Approx(0.0).margin(1e-12));
  CHECK(set.z.real() == Approx(0.5).epsilon(1e-12));
  CHECK(set.thirdPivot.x() == Approx(125.0).epsilon(1e-12));
  CHECK(set.thirdPivot.y() == Approx(0.0).margin(1e-9));
  checkCognates(set);
}

TEST_CASE("100 random Grashof four-bars with random coupler points: the cognates trace the same curve", "[cognates]") {
  std::mt19937 random(46);
  std::uniform_real_distribution<double> length(10.0, 100.0), unit(-1.0, 1.0);
  int checked = 0, drawn = 0;
  while (checked < 100) {
    const FourBarLengths l{length(random), length(random), length(random), length(random)};
    const GrashofReport g = classifyGrashof(l);
    const double total = l.frame + l.crank + l.coupler + l.rocker;
    // A crank that turns fully, kept away from a change point's folded positions.
    if (!g.inputFullyRotates || g.pPlusQ - g.sPlusL < 0.05 * total) continue;
    const CouplerPointSpec p{(0.5 + 0.9 * unit(random)) * l.coupler, unit(random) * l.coupler};
    const std::complex<double> z(p.along / l.coupler, p.across / l.coupler);
    if (std::abs(z) < 0.1 || std::abs(1.0 - z) < 0.1) continue;
    const Branch branch = unit(random) < 0.0 ? Branch::Open : Branch::Crossed;
    // Every other one drawn point by point: frame at 30°, crank phase, coupler link C→B.
    const bool drawnOne = checked % 2 == 1;
    const Design d = drawnOne ? drawnDesign(l, branch, p) : fourBarDesign(l, branch, "mm", p).value();
    drawn += drawnOne ? 1 : 0;
    CAPTURE(checked, l.frame, l.crank, l.coupler, l.rocker, p.along, p.across, drawnOne);
    const auto set = cognates(d);
    REQUIRE(set.ok());
    CHECK(std::abs(set->z - z) < 1e-12 * std::abs(z));
    checkCognates(*set);
    ++checked;
  }
  CHECK(drawn == 50);
}

TEST_CASE("cognates refuses what has no cognates, each in a sentence", "[cognates]") {
  SECTION("not a four-bar") {
    const auto r = cognates(designForExample("ls3-engine").value());
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().code == ErrorCode::InvalidStructure);
    CHECK(r.error().message ==
          "cognates are for a four-bar (a crank, a coupler and a rocker on two ground pivots, "
          "with points fixed on the coupler), and this slider-crank is not one");
  }
  SECTION("no coupler point") {
    const auto r = cognates(designForExample("thesis-crank-rocker").value());
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().field == "couplerPoint");
    CHECK(r.error().message.find("this four-bar has no point fixed on its coupler") == 0);
  }
  SECTION("a name that is not a point on the coupler") {
    for (const std::string name : {"Q", "B", "O2"}) {
      const auto r = cognates(thesisWithCouplerPoint(), name);
      REQUIRE_FALSE(r.ok());
      CHECK(r.error().message ==
            "couplerPoint must name a point fixed on the coupler (got \"" + name + "\"; the points on it: P)");
    }
  }
  SECTION("P at B or at C: a cognate of zero length") {
    const auto atB =
        cognates(fourBarDesign(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{0.0, 0.0}).value());
    REQUIRE_FALSE(atB.ok());
    CHECK(atB.error().message ==
          "the coupler point P is at B, the crank–coupler joint, where cognate 1 shrinks to a "
          "point (its links would have zero length): choose a point away from B and C");
    const auto atC =
        cognates(fourBarDesign(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{70.0, 0.0}).value());
    REQUIRE_FALSE(atC.ok());
    CHECK(atC.error().message.find("is at C, the coupler–rocker joint, where cognate 2 shrinks to a point") !=
          std::string::npos);
  }
  SECTION("P so near B that cognate 1's links are shorter than a linkage may have") {
    const auto r = cognates(fourBarDesign(kThesisCrankRocker, Branch::Open, "mm", CouplerPointSpec{1e-7, 0.0}).value());
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().field == "couplerPoint");
    CHECK(r.error().message.find("cognate 1 would not be a linkage Linkwright can hold") == 0);
  }
  SECTION("a pose that does not assemble") {
    // A Grashof double-rocker swept over a full turn: its crank cannot reach 0°.
    Design d = fourBarDesign({50.0, 60.0, 20.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{10.0, 10.0}).value();
    const auto r = cognates(d);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().code == ErrorCode::NotAssemblable);
    CHECK(r.error().message.find("the four-bar cannot be assembled at the start of its grid, where its cognates are "
                                 "constructed: ") == 0);
  }
}
