// Dragging joints on the canvas: the edit equals the core's dragPoint (with the four-bar's
// frame-line rule) for the drop point,
// one drag is one undo step, and a drag that cannot be assembled changes nothing.

#include "canvas_test_support.h"

#include "ui/canvas/label_item.h"

#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/solve/pose_solver.h"

#include <QSignalSpy>

#include "tests/support/catch.h"

#include <cmath>

namespace k = linkwright::kinematics;
namespace fourbar = linkwright::kinematics::fourbar;
using linkwright::ui::toEigen;
using linkwright::ui::toQt;
using linkwright::ui::test::ShownView;

namespace {

// Scene points come from pixels through the view's transform (mapToScene here, the inverse
// viewport transform in the view): the two round differently in the last bits.
constexpr double kSceneTolerance = 1e-9;

// Where the view aims a drag that grabbed `grabbed` at pixel `press` and let go at `drop`.
QPointF dropTarget(const ShownView& v, const QPointF& grabbed, const QPoint& press, const QPoint& drop) {
  return v.view.mapToScene(drop) - v.view.mapToScene(press) + grabbed;
}

// The core's drag of `point` of `design`'s four-bar, shown at `angle`, to `target`.
k::PointDrag coreDrag(const k::Design& design, double angle, k::PointId point, const QPointF& target) {
  const k::Pose pose = k::solvePose(design.mechanism, {angle, 0.0, 0.0}).value();
  return k::dragPoint(design.mechanism, pose, angle, point, toEigen(target), k::DragRule::FrameLine).value();
}

k::FourBarStructure fourBarOf(const k::Mechanism& m) { return k::asFourBar(m).value(); }

}  // namespace

TEST_CASE("dragging C sets coupler and rocker to reach the drop point and lands C there", "[canvas][drag]") {
  ShownView v;
  const k::Design before = v.document.design();
  const k::FourBarLengths lengthsBefore = v.document.fourBar()->lengths;
  const double angle = v.document.crankAngle();
  const QPointF c = v.point(fourbar::kC);
  const QPoint press = v.pixelOf(c);
  const QPoint drop = press + QPoint(30, 25);
  v.drag(press, drop, 12);

  const QPointF target = dropTarget(v, c, press, drop);
  const k::FourBarStructure expected = fourBarOf(coreDrag(before, angle, fourbar::kC, target).mechanism);
  const k::FourBarLengths& got = v.document.fourBar()->lengths;
  CHECK(got.coupler == Approx(expected.lengths.coupler).margin(kSceneTolerance));
  CHECK(got.rocker == Approx(expected.lengths.rocker).margin(kSceneTolerance));
  CHECK(got.coupler != lengthsBefore.coupler);
  CHECK(got.rocker != lengthsBefore.rocker);
  CHECK(got.crank == lengthsBefore.crank);
  CHECK(got.frame == lengthsBefore.frame);
  CHECK(v.document.fourBar()->branch == expected.branch);
  const QPointF landed = v.point(fourbar::kC);
  CHECK(landed.x() == Approx(target.x()).margin(kSceneTolerance));
  CHECK(landed.y() == Approx(target.y()).margin(kSceneTolerance));
  CHECK(v.scene().handleItem(fourbar::kC)->pos() == landed);

  SECTION("the whole drag is one undo step, and undo restores the design exactly") {
    CHECK(v.document.undoStack()->count() == 1);
    CHECK(v.document.undoStack()->undoText() == "Move C");
    v.document.undoStack()->undo();
    CHECK(v.document.design() == before);
  }
}

TEST_CASE("two drags of the same joint are two undo steps", "[canvas][drag]") {
  ShownView v;
  const k::Design original = v.document.design();
  QPoint press = v.pixelOf(v.point(fourbar::kC));
  v.drag(press, press + QPoint(10, 0));
  const k::Design afterFirst = v.document.design();
  press = v.pixelOf(v.point(fourbar::kC));
  v.drag(press, press + QPoint(0, 12));
  REQUIRE(v.document.undoStack()->count() == 2);
  v.document.undoStack()->undo();
  CHECK(v.document.design() == afterFirst);
  v.document.undoStack()->undo();
  CHECK(v.document.design() == original);
}

TEST_CASE("dragging B changes the crank length and the crank angle", "[canvas][drag]") {
  ShownView v;
  const k::Design before = v.document.design();
  const double angleBefore = v.document.crankAngle();
  const QPointF b = v.point(fourbar::kB);
  const QPoint press = v.pixelOf(b);
  const QPoint drop = press + QPoint(-20, -25);
  v.drag(press, drop);

  const QPointF target = dropTarget(v, b, press, drop);
  const k::PointDrag expected = coreDrag(before, angleBefore, fourbar::kB, target);
  CHECK(v.document.fourBar()->lengths.crank == Approx(std::hypot(target.x(), target.y())).margin(kSceneTolerance));
  CHECK(v.document.fourBar()->lengths.crank ==
        Approx(fourBarOf(expected.mechanism).lengths.crank).margin(kSceneTolerance));
  CHECK(v.document.crankAngle() == Approx(expected.inputAngle).margin(kSceneTolerance));
  CHECK(v.document.crankAngle() != Approx(angleBefore).margin(1e-3));
  CHECK(v.document.undoStack()->count() == 1);
  v.document.undoStack()->undo();
  CHECK(v.document.design() == before);
}

TEST_CASE("dragging P moves the coupler point on the coupler", "[canvas][drag]") {
  const k::Design design =
      k::fourBarDesign(k::kThesisCrankRocker, k::Branch::Open, "mm", k::CouplerPointSpec{30.0, 20.0}).value();
  ShownView v(design);
  const double angle = v.document.crankAngle();
  const QPointF p = v.point(fourbar::kCouplerPoint);
  const QPoint press = v.pixelOf(p);
  const QPoint drop = press + QPoint(15, -10);
  v.drag(press, drop);

  const k::Mechanism expected =
      coreDrag(design, angle, fourbar::kCouplerPoint, dropTarget(v, p, press, drop)).mechanism;
  const auto want = k::couplerPointOf(expected, fourBarOf(expected));
  const auto got = k::couplerPointOf(v.document.mechanism(), *v.document.fourBar());
  REQUIRE(want);
  REQUIRE(got);
  CHECK(got->spec.along == Approx(want->spec.along).margin(kSceneTolerance));
  CHECK(got->spec.across == Approx(want->spec.across).margin(kSceneTolerance));
  CHECK(v.document.fourBar()->lengths == fourBarOf(design.mechanism).lengths);
  CHECK(v.document.undoStack()->undoText() == "Move P");
}

TEST_CASE("dragging O2 changes the frame length and keeps O4 where it was on screen", "[canvas][drag]") {
  ShownView v;
  const double frameBefore = v.document.fourBar()->lengths.frame;
  const QPoint o4Before = v.pixelOf(v.point(fourbar::kO4));
  const QPoint press = v.pixelOf(v.point(fourbar::kO2));
  const QPoint drop = press + QPoint(-40, 0);
  const double shift = (v.view.mapToScene(drop) - v.view.mapToScene(press)).x();
  v.drag(press, drop, 8);

  CHECK(v.document.fourBar()->lengths.frame == Approx(frameBefore - shift).margin(1e-6));
  CHECK(v.document.fourBar()->lengths.frame > frameBefore);
  const QPoint o4After = v.pixelOf(v.point(fourbar::kO4));
  CHECK(std::abs(o4After.x() - o4Before.x()) <= 1);
  CHECK(std::abs(o4After.y() - o4Before.y()) <= 1);
  const QPoint o2After = v.pixelOf(v.point(fourbar::kO2));
  CHECK(std::abs(o2After.x() - drop.x()) <= 1);
  CHECK(v.document.undoStack()->count() == 1);
}

TEST_CASE("a drag that cannot be assembled is refused and changes nothing", "[canvas][drag]") {
  ShownView v;
  const k::Design before = v.document.design();
  QSignalSpy refused(&v.view, &linkwright::ui::LinkageView::editRefused);
  const QPointF b = v.point(fourbar::kB);
  const QPoint press = v.pixelOf(b);
  // B 200 mm further out: crank tip and rocker pivot are then further apart than coupler +
  // rocker can reach, at any crank angle.
  const QPoint far = v.pixelOf(b + QPointF(200.0, 0.0));

  QTest::mousePress(v.viewport(), Qt::LeftButton, Qt::NoModifier, press);
  QTest::mouseMove(v.viewport(), far);
  CHECK(v.scene().messageItem()->isVisible());
  CHECK(v.scene().messageItem()->text().contains("cannot be assembled"));
  QTest::mouseRelease(v.viewport(), Qt::LeftButton, Qt::NoModifier, far);

  CHECK(v.document.design() == before);
  CHECK(v.document.undoStack()->count() == 0);
  REQUIRE(refused.count() >= 1);
  CHECK(refused.first().first().toString().contains("cannot be assembled"));
  CHECK_FALSE(v.scene().messageItem()->isVisible());
}

TEST_CASE("a refused move keeps the last good state of the drag", "[canvas][drag]") {
  ShownView v;
  const k::Design initial = v.document.design();
  const QPointF b = v.point(fourbar::kB);
  const QPoint press = v.pixelOf(b);
  const QPoint good = press + QPoint(8, 8);
  QTest::mousePress(v.viewport(), Qt::LeftButton, Qt::NoModifier, press);
  QTest::mouseMove(v.viewport(), good);
  const k::Design lastGood = v.document.design();
  REQUIRE(lastGood != initial);
  QTest::mouseMove(v.viewport(), v.pixelOf(b + QPointF(200.0, 0.0)));
  CHECK(v.document.design() == lastGood);
  QTest::mouseRelease(v.viewport(), Qt::LeftButton, Qt::NoModifier, v.pixelOf(b + QPointF(200.0, 0.0)));
  CHECK(v.document.design() == lastGood);
  CHECK(v.document.undoStack()->count() == 1);
}

TEST_CASE("hovering a joint offers it for dragging", "[canvas][drag]") {
  ShownView v;
  QSignalSpy status(&v.view, &linkwright::ui::LinkageView::statusMessage);
  QTest::mouseMove(v.viewport(), v.pixelOf(v.point(fourbar::kC)));
  CHECK(v.viewport()->cursor().shape() == Qt::OpenHandCursor);
  REQUIRE(status.count() >= 1);
  CHECK(status.last().first().toString().contains("Drag C"));
  QTest::mouseMove(v.viewport(), QPoint(5, 5));
  CHECK(v.viewport()->cursor().shape() != Qt::OpenHandCursor);
}
