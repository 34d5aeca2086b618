// Linkages driven other than by a crank (driven_linkages.h): a two-link arm whose tip follows
// a path, a slider-crank driven from its piston and a cylinder-driven boom. Seed 004's arm,
// swept on its time base, equals the closed-form inverse kinematics (two_link_arm.h) column by
// column for both elbows; every driver's rates are the time derivatives of its positions; the
// piston-driven slider-crank agrees with the crank-driven one at the same pose; closure holds.

#include "kinematics/model/driven_linkages.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/analysis/two_link_arm.h"
#include "kinematics/design/design.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/rigid_bodies.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <sstream>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::checkAllRatesAgainstDifferences;
using linkwright::test::within;

namespace {

constexpr PointId kTip{1};
constexpr PointId kElbow{2};
constexpr std::size_t kUpper = 0;
constexpr std::size_t kForearm = 1;

Design seedArm(Branch elbow) {
  Design d = designForExample("seed-arm").value();
  std::get<RrrPoint>(d.mechanism.points[kElbow.index].definition).branch = elbow;
  return d;
}

}  // namespace

TEST_CASE("seed 004's arm swept on its time base equals the closed-form inverse kinematics",
          "[driven][arm][published]") {
  const TwoLinkArm arm{0.3, 0.2};
  const LinePath path{{0.3, 0.0}, {0.0, 0.3}, 2.0};
  for (const Branch elbow : {Branch::Crossed, Branch::Open}) {
    CAPTURE(elbow == Branch::Open ? "elbow up" : "elbow down");
    const Design d = seedArm(elbow);
    const auto swept = sweep(d.mechanism, designSweepSpec(d));
    REQUIRE(swept);
    const auto reference = followLine(arm, elbow, path, d.samples);
    REQUIRE(reference);
    REQUIRE(swept->size() == 101);
    for (std::size_t j = 0; j < swept->size(); ++j) {
      const ArmSample& s = reference->samples[j];
      CAPTURE(j, s.time);
      REQUIRE(s.reachable);
      REQUIRE(swept->ok(j));
      CHECK(swept->time[j] == within(s.time, 1e-15));
      CHECK((swept->position[kTip.index][j] - s.tip).norm() < 1e-15);
      CHECK((swept->position[kElbow.index][j] - s.state.elbow).norm() < 1e-15);
      CHECK(std::abs(angleDifference(swept->linkAngle[kUpper][j], s.state.upperAngle)) < 1e-12);
      CHECK(std::abs(angleDifference(swept->linkAngle[kForearm][j], s.state.forearmAngle)) < 1e-12);
      CHECK(swept->linkOmega[kUpper][j] == within(s.state.upperOmega, 1e-12));
      CHECK(swept->linkOmega[kForearm][j] == within(s.state.forearmOmega, 1e-12));
      CHECK(swept->linkAlpha[kUpper][j] == within(s.state.upperAlpha, 1e-12));
      CHECK(swept->linkAlpha[kForearm][j] == within(s.state.forearmAlpha, 1e-12));
    }
  }
  // The seed's start, elbow down: upper −38.9424°, forearm 70.5288°, ω 3.04738 and 10.54738.
  const auto start = sweep(seedArm(Branch::Crossed).mechanism, designSweepSpec(seedArm(Branch::Crossed))).value();
  CHECK(radToDeg(start.linkAngle[kUpper][0]) == within(-38.9424, 5e-5));
  CHECK(radToDeg(start.linkAngle[kForearm][0]) == within(70.5288, 5e-5));
  CHECK(start.linkOmega[kUpper][0] == within(3.04738, 5e-6));
  CHECK(start.linkOmega[kForearm][0] == within(10.54738, 5e-6));
}

TEST_CASE("the arm's CSV runs on time with the tip's path coordinate as its input", "[driven][arm][io]") {
  const Design d = seedArm(Branch::Crossed);
  const SweepResult r = sweep(d.mechanism, designSweepSpec(d)).value();
  std::ostringstream csv;
  io::writeSweepCsv(csv, d.mechanism, r);
  const std::string header = csv.str().substr(0, csv.str().find('\r'));
  CHECK(header.rfind("time_s,tip_s_m,upper_angle_deg,upper_omega_rad_s,upper_alpha_rad_s2,forearm_angle_deg,", 0) == 0);
  CHECK(inputKind(d.mechanism) == InputKind::Length);
  CHECK(inputName(d.mechanism) == "tip path position");
  // The tip moves at 2 m/s along the path: s = 2t.
  for (std::size_t j = 0; j < r.size(); ++j) CHECK(r.inputAngle[j] == within(2.0 * r.time[j], 1e-15));
}

TEST_CASE("every driver's rates are the time derivatives of its positions", "[driven][properties]") {
  SECTION("a tip driven along a straight path, speeding up") {
    checkAllRatesAgainstDifferences(seedArm(Branch::Crossed).mechanism, {0.1, 2.0, 15.0}, 0.5);
  }
  SECTION("a tip driven along an arc, both ways") {
    for (const double sweepAngle : {1.5, -1.5}) {
      CAPTURE(sweepAngle);
      const Mechanism m =
          makeTwoLinkArm({0.3, 0.2, ArcPath{{0.1, 0.1}, 0.2, 0.3, sweepAngle}, Branch::Open, "m"}).value();
      checkAllRatesAgainstDifferences(m, {0.12, -0.7, 4.0}, 0.5);
    }
  }
  SECTION("a piston driving its crank") {
    checkAllRatesAgainstDifferences(makePistonDriven({}).value(), {30.0, 900.0, -2e4}, 180.0);
  }
  SECTION("a cylinder driving a boom") {
    checkAllRatesAgainstDifferences(makeCylinderRocker({}).value(), {1.5, 0.3, -0.2}, 3.0);
  }
}

TEST_CASE("a piston-driven slider-crank moves as the crank-driven one at the same pose", "[driven][slider]") {
  const Mechanism driven = makePistonDriven({40.0, 140.0, Branch::Open, "mm"}).value();
  const Mechanism cranked = makeSliderCrank({40.0, 140.0, 0.0, false}).value();
  const double sDot = 1200.0;  // mm/s, the piston's speed
  const double sDdot = -3e4;   // mm/s²
  for (const double s : {5.0, 23.0, 40.0, 61.0, 77.0}) {
    CAPTURE(s);
    const Pose p = solvePose(driven, {s, sDot, sDdot}).value();
    const double crankAngle = p.linkAngle[0];
    // At the crank's angle, ω = 1 and α = 0 give the piston's dx/dθ and d²x/dθ²; the piston's
    // ṡ = x'·ω and s̈ = x'·α + x''·ω² then give the crank's ω and α.
    const Pose unit = solvePose(cranked, {crankAngle, 1.0, 0.0}).value();
    const double xPrime = unit.velocity[slidercrank::kC.index].x();
    const double xSecond = unit.acceleration[slidercrank::kC.index].x();
    const double omega = sDot / xPrime;
    const double alpha = (sDdot - xSecond * omega * omega) / xPrime;
    CHECK(p.position[1].x() == within(unit.position[slidercrank::kC.index].x(), 1e-12));
    CHECK(p.linkOmega[0] == Approx(omega).epsilon(1e-12));
    CHECK(p.linkAlpha[0] == Approx(alpha).epsilon(1e-11));
  }
}

TEST_CASE("driven points keep their paths and actuators their lengths", "[driven][closure]") {
  const ArcPath arc{{0.1, 0.1}, 0.2, 0.3, 1.5};
  const Mechanism arm = makeTwoLinkArm({0.3, 0.2, arc, Branch::Open, "m"}).value();
  const Mechanism boom = makeCylinderRocker({}).value();
  for (const double q : {0.0, 0.1, 0.25, 0.3}) {
    const Pose p = solvePose(arm, {q, 1.0, 0.0}).value();
    CHECK((p.position[kTip.index] - arc.centre).norm() == within(0.2, 1e-15));
    CHECK(p.position[kTip.index].isApprox(pathAt(arc, q).point, 1e-15));
    CHECK(p.velocity[kTip.index].norm() == within(1.0, 1e-15));
  }
  for (const double stroke : {1.2, 1.5, 1.9}) {
    const Pose p = solvePose(boom, {stroke, 0.1, 0.0}).value();
    CHECK((p.position[2] - p.position[1]).norm() == within(stroke, 1e-14));
    CHECK(p.position[2].norm() == within(1.0, 1e-15));
    CHECK(p.position[3].norm() == within(2.8, 1e-14));
  }
}

TEST_CASE("a polyline path runs on along its segments and past its ends", "[driven][path]") {
  const PolylinePath line{{{0.0, 0.0}, {3.0, 4.0}, {3.0, 10.0}}};
  CHECK(pathLength(line) == 11.0);
  CHECK(pathAt(line, 2.5).point.isApprox(Eigen::Vector2d(1.5, 2.0)));
  CHECK(pathAt(line, 7.0).point.isApprox(Eigen::Vector2d(3.0, 6.0)));
  CHECK(pathAt(line, -5.0).point.isApprox(Eigen::Vector2d(-3.0, -4.0)));
  CHECK(pathAt(line, 12.0).point.isApprox(Eigen::Vector2d(3.0, 11.0)));
  CHECK(nearestPathCoordinate(line, {5.0, 7.0}) == within(8.0, 1e-15));
  CHECK(nearestPathCoordinate(line, {-1.0, -1.0}) == 0.0);
  const ArcPath arc{{0.0, 0.0}, 2.0, 0.0, -kPi};
  CHECK(pathAt(arc, kPi).point.isApprox(Eigen::Vector2d(0.0, -2.0)));
  CHECK(nearestPathCoordinate(arc, {1.0, -1.0}) == within(0.5 * kPi, 1e-15));
  CHECK(nearestPathCoordinate(arc, {1.0, 0.1}) == 0.0);
}

TEST_CASE("each driver adds one degree of freedom", "[driven][mobility]") {
  CHECK(mobility(seedArm(Branch::Crossed).mechanism).mobility == 1);
  CHECK(mobility(makePistonDriven({}).value()).mobility == 1);
  CHECK(mobility(makeCylinderRocker({}).value()).mobility == 1);
}

TEST_CASE("dragging a driven point moves the input along its path", "[driven][drag]") {
  const Design d = seedArm(Branch::Crossed);
  const Pose pose = solvePose(d.mechanism, {0.1, 0.0, 0.0}).value();
  const auto drag = dragPoint(d.mechanism, pose, 0.1, kTip, {0.2, 0.2});
  REQUIRE(drag);
  CHECK(drag->mechanism == d.mechanism);
  CHECK(drag->inputAngle == within(0.15 * std::sqrt(2.0), 1e-15));  // at (0.15, 0.15), nearest (0.2, 0.2)
}

TEST_CASE("bad drivers are refused with the field and the reason", "[driven][errors]") {
  Mechanism m = seedArm(Branch::Crossed).mechanism;
  std::get<PathPoint>(m.points[kTip.index].definition).path = PolylinePath{{{0.3, 0.0}}};
  auto e = checkMechanism(m);
  REQUIRE(e);
  CHECK(e->field == "points[1].path.vertices");
  CHECK(e->message == "points[1].path.vertices needs at least two points (got 1)");
  std::get<PathPoint>(m.points[kTip.index].definition).path = PolylinePath{{{0.3, 0.0}, {0.3, 0.0}}};
  e = checkMechanism(m);
  REQUIRE(e);
  CHECK(e->field == "points[1].path.vertices[1]");
  std::get<PathPoint>(m.points[kTip.index].definition).path = ArcPath{{0.0, 0.0}, 0.2, 0.0, 0.0};
  e = checkMechanism(m);
  REQUIRE(e);
  CHECK(e->message == "points[1].path.sweep must be non-zero and within ±360° (got 0°)");

  Mechanism boom = makeCylinderRocker({}).value();
  std::get<ActuatorPoint>(boom.points[2].definition).base = PointId{0};
  e = checkMechanism(boom);
  REQUIRE(e);
  CHECK(e->message == "points[2].base must differ from its first point");

  // A second driver: exactly one is allowed.
  Mechanism two = makeCylinderRocker({}).value();
  two.points.push_back({"D", CrankPoint{PointId{0}, 0.5, 0.0}});
  e = checkMechanism(two);
  REQUIRE(e);
  CHECK(e->message ==
        "points must contain exactly one driver: a crank, a point on a path or a linear actuator (got 2)");
}

TEST_CASE("a linkage that cannot follow its driver says where, in the driver's own units", "[driven][errors]") {
  const Mechanism boom = makeCylinderRocker({}).value();
  const auto tooShort = solvePose(boom, {0.05, 0.0, 0.0});
  REQUIRE_FALSE(tooShort);
  CHECK(tooShort.error().message ==
        "C cannot be assembled at actuator A–C length 0.05 m: O and A are 0.948683 m apart, less than |boom − "
        "actuator| = 0.95 m");
  const Design arm = seedArm(Branch::Crossed);
  const auto outside = solvePose(arm.mechanism, {-0.3, 0.0, 0.0});
  REQUIRE_FALSE(outside);
  CHECK(outside.error().message.rfind("elbow cannot be assembled at tip path position -0.3 m: O and tip are", 0) == 0);
}

TEST_CASE("forces take a linear driver: the actuator's force is its unknown", "[driven][dynamics]") {
  const auto model = bodiesOf(makeCylinderRocker({}).value());
  CHECK((model.ok() && model->drive.kind == DriveKind::Actuator));
}

TEST_CASE("the stretches of a path outside the arm's reach are exact", "[driven][path][arm]") {
  // arm --from-point 0.3,0 --to-point 0.7,0 at 2 m/s: unreachable from t = 0.1 s to 0.2 s.
  const TwoLinkArm arm{0.3, 0.2};
  const LinePath line{{0.3, 0.0}, {0.7, 0.0}, 2.0};
  const auto reference = followLine(arm, Branch::Open, line, 2).value();
  const PolylinePath path{{line.from, line.to}};
  const auto outside = pathOutsideAnnulus(path, Eigen::Vector2d::Zero(), 0.1, 0.5);
  REQUIRE(outside.size() == 1);
  REQUIRE(reference.unreachable.size() == 1);
  CHECK(outside[0].first / line.speed == within(reference.unreachable[0].first, 1e-15));
  CHECK(outside[0].second / line.speed == within(reference.unreachable[0].second, 1e-15));
  // An arc through the outer circle twice and a polyline through the inner one: each stretch
  // ends on a circle, and its middle lies outside the annulus.
  for (const PathShape& shape : {PathShape{ArcPath{{0.6, 0.0}, 0.25, kPi, -kPi}},
                                 PathShape{PolylinePath{{{-0.4, 0.05}, {0.4, 0.05}, {0.4, 0.6}}}}}) {
    const auto stretches = pathOutsideAnnulus(shape, Eigen::Vector2d::Zero(), 0.1, 0.5);
    REQUIRE_FALSE(stretches.empty());
    for (const auto& [from, to] : stretches) {
      CAPTURE(from, to);
      const double middle = pathAt(shape, 0.5 * (from + to)).point.norm();
      CHECK((middle < 0.1 || middle > 0.5));
      for (const double s : {from, to}) {
        if (s == 0.0 || s == pathLength(shape)) continue;
        const double r = pathAt(shape, s).point.norm();
        CHECK(std::min(std::abs(r - 0.1), std::abs(r - 0.5)) < 1e-15);
      }
    }
  }
}

TEST_CASE("a path's vertex drags to its target, never onto its neighbour", "[driven][drag]") {
  const Mechanism arm = seedArm(Branch::Crossed).mechanism;
  const auto moved = dragPathVertex(arm, kTip, 1, {0.1, 0.4});
  REQUIRE(moved);
  const auto& line = std::get<PolylinePath>(std::get<PathPoint>(moved->points[kTip.index].definition).path);
  CHECK(line.vertices[1] == Eigen::Vector2d(0.1, 0.4));
  const auto onto = dragPathVertex(arm, kTip, 1, {0.3, 0.0});
  REQUIRE_FALSE(onto);
  CHECK(onto.error().message ==
        "point 2 of tip's path cannot be dropped onto point 1: the segment between them would have no length");
  CHECK_FALSE(dragPathVertex(arm, kTip, 2, {0.0, 0.0}));
  CHECK_FALSE(dragPathVertex(arm, kElbow, 0, {0.0, 0.0}));
}
