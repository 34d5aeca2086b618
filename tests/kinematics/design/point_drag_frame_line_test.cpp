// Dragging a four-bar's points under DragRule::FrameLine (kinematics/design/point_drag.h):
// each handle changes exactly the lengths it should, the dragged point ends where it was
// dropped, the pivots stay on the frame line, and impossible drags are refused with a reason.

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/kinematics/design/drawn_fourbar.h"
#include "tests/support/approx.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

Pose poseAt(const Mechanism& m, double inputAngle) {
  const auto pose = solvePose(m, {inputAngle, 0.0, 0.0}, {false, false});
  INFO((pose.ok() ? std::string() : pose.error().message));
  REQUIRE(pose.ok());
  return *pose;
}

Eigen::Vector2d pointAt(const PointDrag& d, PointId id) { return poseAt(d.mechanism, d.inputAngle).position[id.index]; }

FourBarStructure fourBarOf(const PointDrag& d) {
  const auto s = asFourBar(d.mechanism);
  REQUIRE(s.has_value());
  return *s;
}

// The thesis crank-rocker with the coupler point the GUI shows.
Mechanism thesis() { return makeFourBar({60, 25, 70, 45}, Branch::Open, "mm", CouplerPointSpec{35, 20}).value(); }

Result<PointDrag> drag(const Mechanism& m, double inputAngle, PointId point, const Eigen::Vector2d& target) {
  return dragPoint(m, poseAt(m, inputAngle), inputAngle, point, target, DragRule::FrameLine);
}

}  // namespace

TEST_CASE("dragging C sets coupler and rocker and lands C on the target", "[model][drag]") {
  const Eigen::Vector2d target(80, 45);
  const auto o = drag(thesis(), 0.5, fourbar::kC, target);
  REQUIRE(o.ok());
  CHECK(fourBarOf(*o).lengths.frame == 60);
  CHECK(fourBarOf(*o).lengths.crank == 25);
  CHECK(o->inputAngle == 0.5);
  CHECK((pointAt(*o, fourbar::kC) - target).norm() < 1e-9);
}

TEST_CASE("dragging C to the other side of B-O4 switches the branch", "[model][drag]") {
  const auto o = drag(thesis(), 0.0, fourbar::kC, {70, -30});
  REQUIRE(o.ok());
  CHECK(fourBarOf(*o).branch == Branch::Crossed);
  CHECK((pointAt(*o, fourbar::kC) - Eigen::Vector2d(70, -30)).norm() < 1e-9);
}

TEST_CASE("dragging B sets crank length and angle", "[model][drag]") {
  const auto o = drag(thesis(), 0.0, fourbar::kB, {0, 20});
  REQUIRE(o.ok());
  CHECK(fourBarOf(*o).lengths.crank == Approx(20));
  CHECK(o->inputAngle == Approx(kPi / 2));
  CHECK(fourBarOf(*o).crankPhase == 0.0);  // the input turns, not the crank's phase
  CHECK(fourBarOf(*o).lengths.coupler == 70);
}

TEST_CASE("dragging the pivots along the frame line changes the frame", "[model][drag]") {
  const auto o4 = drag(thesis(), 0.0, fourbar::kO4, {65, 12});  // y is ignored: O4 stays on the line
  REQUIRE(o4.ok());
  CHECK(fourBarOf(*o4).lengths.frame == 65);
  CHECK(pointAt(*o4, fourbar::kO4) == Eigen::Vector2d(65, 0));
  const auto o2 = drag(thesis(), 0.0, fourbar::kO2, {-5, 3});
  REQUIRE(o2.ok());
  CHECK(fourBarOf(*o2).lengths.frame == 65);
  // O2 moves along the frame line; O4 stays where it was (the frame is no longer re-anchored
  // at the origin).
  CHECK(pointAt(*o2, fourbar::kO2) == Eigen::Vector2d(-5, 0));
  CHECK(pointAt(*o2, fourbar::kO4) == Eigen::Vector2d(60, 0));
  CHECK(fourBarOf(*o2).frameAngle == 0.0);
  CHECK(o2->inputAngle == 0.0);
}

TEST_CASE("dragging the coupler point keeps it where it was dropped", "[model][drag]") {
  const Eigen::Vector2d target(40, 60);
  const auto o = drag(thesis(), 1.0, fourbar::kCouplerPoint, target);
  REQUIRE(o.ok());
  CHECK(fourBarOf(*o).lengths == FourBarLengths{60, 25, 70, 45});
  CHECK((pointAt(*o, fourbar::kCouplerPoint) - target).norm() < 1e-9);
}

TEST_CASE("impossible drags are refused with the reason", "[model][drag][errors]") {
  const auto pastO2 = drag(thesis(), 0.0, fourbar::kO4, {-10, 0});
  REQUIRE_FALSE(pastO2.ok());
  CHECK(pastO2.error().field == "O4");
  CHECK_THAT(pastO2.error().message, Catch::Contains("O4 cannot pass O2") && Catch::Contains("no length"));
  const auto pastO4 = drag(thesis(), 0.0, fourbar::kO2, {70, 0});
  REQUIRE_FALSE(pastO4.ok());
  CHECK_THAT(pastO4.error().message, Catch::Contains("O2 cannot pass O4"));
  const auto onPivot = drag(thesis(), 0.0, fourbar::kB, {0, 0});
  REQUIRE_FALSE(onPivot.ok());
  CHECK_THAT(onPivot.error().message, Catch::Contains("B cannot be dropped onto O2") && Catch::Contains("no length"));
  // A crank of 100 puts B 160 from O4 at 180°: coupler + rocker (115) cannot reach. The drag
  // itself does not solve; the pose at the returned input angle says why it fails.
  const auto tooLong = drag(thesis(), 0.0, fourbar::kB, {-100, 0});
  REQUIRE(tooLong.ok());
  const auto pose = solvePose(tooLong->mechanism, {tooLong->inputAngle, 0.0, 0.0}, {false, false});
  REQUIRE_FALSE(pose.ok());
  CHECK(pose.error().code == ErrorCode::NotAssemblable);
  CHECK_THAT(pose.error().message, Catch::Contains("cannot be assembled"));
}

TEST_CASE("the frame-line rule follows a four-bar drawn in any position", "[model][drag]") {
  using namespace linkwright::test;
  const DrawnFourBar d = drawnFourBar({60, 25, 70, 45}, Branch::Open, CouplerPointSpec{35, 20});
  const Eigen::Vector2d along(std::cos(d.frameAngle), std::sin(d.frameAngle));
  const Eigen::Vector2d normal(-along.y(), along.x());
  const double input = 0.7;

  // O2 slides along the 30° frame line, whatever the target's offset across it; O4 stays.
  const auto o2 = drag(d.mechanism, input, kDrawnO2, d.origin + 10.0 * along + 7.0 * normal);
  REQUIRE(o2.ok());
  CHECK(fourBarOf(*o2).lengths.frame == within(50.0, 1e-12));
  CHECK(fourBarOf(*o2).frameAngle == within(d.frameAngle, 1e-15));
  CHECK((pointAt(*o2, kDrawnO2) - (d.origin + 10.0 * along)).norm() < 1e-12);
  CHECK(pointAt(*o2, kDrawnO4) == poseAt(d.mechanism, input).position[kDrawnO4.index]);
  const auto o4 = drag(d.mechanism, input, kDrawnO4, d.origin + 65.0 * along - 3.0 * normal);
  REQUIRE(o4.ok());
  CHECK(fourBarOf(*o4).lengths.frame == within(65.0, 1e-12));
  const auto passed = drag(d.mechanism, input, kDrawnO4, d.origin - 5.0 * along);
  REQUIRE_FALSE(passed.ok());
  CHECK_THAT(passed.error().message, Catch::Contains("O4 cannot pass O2"));

  // B sets the crank's length and turns the input; the crank's phase stays.
  const Eigen::Vector2d target = d.origin + Eigen::Vector2d(-12, 16);
  const auto b = drag(d.mechanism, input, kDrawnB, target);
  REQUIRE(b.ok());
  CHECK(fourBarOf(*b).lengths.crank == within(20.0, 1e-12));
  CHECK(fourBarOf(*b).crankPhase == d.crankPhase);
  CHECK(b->inputAngle == within(std::atan2(16.0, -12.0) - d.crankPhase, 1e-15));
  CHECK((pointAt(*b, kDrawnB) - target).norm() < 1e-12);

  // C and P drag as under the free rule: C's lengths and side, P's offsets.
  const auto c = drag(d.mechanism, input, kDrawnC, d.origin + Eigen::Vector2d(30, 60));
  REQUIRE(c.ok());
  CHECK(fourBarOf(*c).lengths.crank == 25);
  CHECK(c->inputAngle == input);
  CHECK((pointAt(*c, kDrawnC) - (d.origin + Eigen::Vector2d(30, 60))).norm() < 1e-9);
  const auto free =
      dragPoint(d.mechanism, poseAt(d.mechanism, input), input, kDrawnC, d.origin + Eigen::Vector2d(30, 60));
  REQUIRE(free.ok());
  CHECK(*free == *c);
  const auto p = drag(d.mechanism, input, kDrawnP, d.origin + Eigen::Vector2d(20, 40));
  REQUIRE(p.ok());
  CHECK((pointAt(*p, kDrawnP) - (d.origin + Eigen::Vector2d(20, 40))).norm() < 1e-9);
}

TEST_CASE("the free rule still moves a four-bar's pivot anywhere and B's phase", "[model][drag]") {
  const Mechanism m = thesis();
  const auto o2 = dragPoint(m, poseAt(m, 0.0), 0.0, fourbar::kO2, {-5, 3});
  REQUIRE(o2.ok());
  CHECK(pointAt(*o2, fourbar::kO2) == Eigen::Vector2d(-5, 3));
  const auto b = dragPoint(m, poseAt(m, 0.0), 0.0, fourbar::kB, {0, 20});
  REQUIRE(b.ok());
  CHECK(b->inputAngle == 0.0);
  CHECK(fourBarOf(*b).crankPhase == Approx(kPi / 2));
}
