// Dragging a four-bar's points: each handle changes exactly the lengths it should, the
// dragged point ends where it was dropped, and impossible drags are refused with a reason.

#include "kinematics/design/design_edit.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <catch2/catch.hpp>

using namespace linkwright::kinematics;

namespace {

Eigen::Vector2d pointAt(const DragOutcome& o, PointId id) {
  const auto m = buildMechanism(o.design);
  REQUIRE(m.ok());
  const auto pose = solvePose(*m, {o.crankAngle, 0.0, 0.0}, {false, false});
  REQUIRE(pose.ok());
  return pose->position[id.index];
}

FourBarDesign thesis() {
  FourBarDesign d;
  d.lengths = {60, 25, 70, 45};
  d.couplerPoint = CouplerPointSpec{35, 20};
  return d;
}

}  // namespace

TEST_CASE("dragging C sets coupler and rocker and lands C on the target", "[model][drag]") {
  const Eigen::Vector2d target(80, 45);
  const auto o = dragFourBar(thesis(), 0.5, FourBarHandle::C, target);
  REQUIRE(o.ok());
  CHECK(o->design.lengths.frame == 60);
  CHECK(o->design.lengths.crank == 25);
  CHECK(o->crankAngle == 0.5);
  CHECK((pointAt(*o, fourbar::kC) - target).norm() < 1e-9);
}

TEST_CASE("dragging C to the other side of B-O4 switches the branch", "[model][drag]") {
  const auto o = dragFourBar(thesis(), 0.0, FourBarHandle::C, {70, -30});
  REQUIRE(o.ok());
  CHECK(o->design.branch == Branch::Crossed);
  CHECK((pointAt(*o, fourbar::kC) - Eigen::Vector2d(70, -30)).norm() < 1e-9);
}

TEST_CASE("dragging B sets crank length and angle", "[model][drag]") {
  const auto o = dragFourBar(thesis(), 0.0, FourBarHandle::B, {0, 20});
  REQUIRE(o.ok());
  CHECK(o->design.lengths.crank == Approx(20));
  CHECK(o->crankAngle == Approx(kPi / 2));
  CHECK(o->design.lengths.coupler == 70);
}

TEST_CASE("dragging the pivots along the frame line changes the frame", "[model][drag]") {
  const auto o4 = dragFourBar(thesis(), 0.0, FourBarHandle::O4, {65, 12});  // y is ignored: O4 stays on the line
  REQUIRE(o4.ok());
  CHECK(o4->design.lengths.frame == 65);
  const auto o2 = dragFourBar(thesis(), 0.0, FourBarHandle::O2, {-5, 3});
  REQUIRE(o2.ok());
  CHECK(o2->design.lengths.frame == 65);
  CHECK(o2->originShift == -5);
}

TEST_CASE("dragging the coupler point keeps it where it was dropped", "[model][drag]") {
  const Eigen::Vector2d target(40, 60);
  const auto o = dragFourBar(thesis(), 1.0, FourBarHandle::CouplerPoint, target);
  REQUIRE(o.ok());
  CHECK((pointAt(*o, fourbar::kCouplerPoint) - target).norm() < 1e-9);
}

TEST_CASE("impossible drags are refused with the reason", "[model][drag][errors]") {
  const auto pastO2 = dragFourBar(thesis(), 0.0, FourBarHandle::O4, {-10, 0});
  REQUIRE_FALSE(pastO2.ok());
  CHECK_THAT(pastO2.error().message, Catch::Contains("frame length must be positive"));
  const auto onPivot = dragFourBar(thesis(), 0.0, FourBarHandle::B, {0, 0});
  REQUIRE_FALSE(onPivot.ok());
  CHECK_THAT(onPivot.error().message, Catch::Contains("crank length must be positive"));
  // A crank of 100 puts B 160 from O4 at 180°: coupler + rocker (115) cannot reach.
  const auto tooLong = dragFourBar(thesis(), 0.0, FourBarHandle::B, {-100, 0});
  REQUIRE_FALSE(tooLong.ok());
  CHECK(tooLong.error().code == ErrorCode::NotAssemblable);
  CHECK_THAT(tooLong.error().message, Catch::Contains("cannot be assembled"));
}
