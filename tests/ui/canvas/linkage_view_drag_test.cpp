// Dragging joints on the canvas: the edit equals the core's dragFourBar for the drop point,
// one drag is one undo step, and a drag that cannot be assembled changes nothing.

#include "canvas_test_support.h"

#include "ui/canvas/label_item.h"

#include "kinematics/design/design_edit.h"

#include <QSignalSpy>

#include <catch2/catch.hpp>

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

}  // namespace

TEST_CASE("dragging C sets coupler and rocker to reach the drop point and lands C there", "[canvas][drag]") {
  ShownView v;
  const k::FourBarDesign before = *v.document.fourBar();
  const double angle = v.document.crankAngle();
  const QPointF c = v.point(fourbar::kC);
  const QPoint press = v.pixelOf(c);
  const QPoint drop = press + QPoint(30, 25);
  v.drag(press, drop, 12);

  const QPointF target = dropTarget(v, c, press, drop);
  const auto expected = k::dragFourBar(before, angle, k::FourBarHandle::C, toEigen(target));
  REQUIRE(expected);
  const k::FourBarLengths& got = v.document.fourBar()->lengths;
  CHECK(got.coupler == Approx(expected->design.lengths.coupler).margin(kSceneTolerance));
  CHECK(got.rocker == Approx(expected->design.lengths.rocker).margin(kSceneTolerance));
  CHECK(got.coupler != before.lengths.coupler);
  CHECK(got.rocker != before.lengths.rocker);
  CHECK(got.crank == before.lengths.crank);
  CHECK(got.frame == before.lengths.frame);
  CHECK(v.document.fourBar()->branch == expected->design.branch);
  const QPointF landed = v.point(fourbar::kC);
  CHECK(landed.x() == Approx(target.x()).margin(kSceneTolerance));
  CHECK(landed.y() == Approx(target.y()).margin(kSceneTolerance));
  CHECK(v.scene().handleItem(k::FourBarHandle::C)->pos() == landed);

  SECTION("the whole drag is one undo step, and undo restores the design exactly") {
    CHECK(v.document.undoStack()->count() == 1);
    CHECK(v.document.undoStack()->undoText() == "Move C");
    v.document.undoStack()->undo();
    CHECK(*v.document.fourBar() == before);
  }
}

TEST_CASE("two drags of the same joint are two undo steps", "[canvas][drag]") {
  ShownView v;
  const k::FourBarDesign original = *v.document.fourBar();
  QPoint press = v.pixelOf(v.point(fourbar::kC));
  v.drag(press, press + QPoint(10, 0));
  const k::FourBarDesign afterFirst = *v.document.fourBar();
  press = v.pixelOf(v.point(fourbar::kC));
  v.drag(press, press + QPoint(0, 12));
  REQUIRE(v.document.undoStack()->count() == 2);
  v.document.undoStack()->undo();
  CHECK(*v.document.fourBar() == afterFirst);
  v.document.undoStack()->undo();
  CHECK(*v.document.fourBar() == original);
}

TEST_CASE("dragging B changes the crank length and the crank angle", "[canvas][drag]") {
  ShownView v;
  const k::FourBarDesign before = *v.document.fourBar();
  const double angleBefore = v.document.crankAngle();
  const QPointF b = v.point(fourbar::kB);
  const QPoint press = v.pixelOf(b);
  const QPoint drop = press + QPoint(-20, -25);
  v.drag(press, drop);

  const QPointF target = dropTarget(v, b, press, drop);
  const auto expected = k::dragFourBar(before, angleBefore, k::FourBarHandle::B, toEigen(target));
  REQUIRE(expected);
  CHECK(v.document.fourBar()->lengths.crank == Approx(std::hypot(target.x(), target.y())).margin(kSceneTolerance));
  CHECK(v.document.fourBar()->lengths.crank == Approx(expected->design.lengths.crank).margin(kSceneTolerance));
  CHECK(v.document.crankAngle() == Approx(expected->crankAngle).margin(kSceneTolerance));
  CHECK(v.document.crankAngle() != Approx(angleBefore).margin(1e-3));
  CHECK(v.document.undoStack()->count() == 1);
  v.document.undoStack()->undo();
  CHECK(*v.document.fourBar() == before);
}

TEST_CASE("dragging P moves the coupler point on the coupler", "[canvas][drag]") {
  k::FourBarDesign design;
  design.couplerPoint = k::CouplerPointSpec{30.0, 20.0};
  ShownView v(design);
  const double angle = v.document.crankAngle();
  const QPointF p = v.point(fourbar::kCouplerPoint);
  const QPoint press = v.pixelOf(p);
  const QPoint drop = press + QPoint(15, -10);
  v.drag(press, drop);

  const auto expected =
      k::dragFourBar(design, angle, k::FourBarHandle::CouplerPoint, toEigen(dropTarget(v, p, press, drop)));
  REQUIRE(expected);
  REQUIRE(v.document.fourBar()->couplerPoint);
  CHECK(v.document.fourBar()->couplerPoint->along ==
        Approx(expected->design.couplerPoint->along).margin(kSceneTolerance));
  CHECK(v.document.fourBar()->couplerPoint->across ==
        Approx(expected->design.couplerPoint->across).margin(kSceneTolerance));
  CHECK(v.document.fourBar()->lengths == design.lengths);
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
  const k::FourBarDesign before = *v.document.fourBar();
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

  CHECK(*v.document.fourBar() == before);
  CHECK(v.document.undoStack()->count() == 0);
  REQUIRE(refused.count() >= 1);
  CHECK(refused.first().first().toString().contains("cannot be assembled"));
  CHECK_FALSE(v.scene().messageItem()->isVisible());
}

TEST_CASE("a refused move keeps the last good state of the drag", "[canvas][drag]") {
  ShownView v;
  const k::FourBarDesign initial = *v.document.fourBar();
  const QPointF b = v.point(fourbar::kB);
  const QPoint press = v.pixelOf(b);
  const QPoint good = press + QPoint(8, 8);
  QTest::mousePress(v.viewport(), Qt::LeftButton, Qt::NoModifier, press);
  QTest::mouseMove(v.viewport(), good);
  const k::FourBarDesign lastGood = *v.document.fourBar();
  REQUIRE(lastGood != initial);
  QTest::mouseMove(v.viewport(), v.pixelOf(b + QPointF(200.0, 0.0)));
  CHECK(*v.document.fourBar() == lastGood);
  QTest::mouseRelease(v.viewport(), Qt::LeftButton, Qt::NoModifier, v.pixelOf(b + QPointF(200.0, 0.0)));
  CHECK(*v.document.fourBar() == lastGood);
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
