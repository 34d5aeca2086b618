// Zoom about the cursor, pan by dragging the background, fit to the drawing.

#include "canvas_test_support.h"

#include "tests/support/catch.h"

#include <cmath>

namespace k = linkwright::kinematics;
namespace fourbar = linkwright::kinematics::fourbar;
using linkwright::ui::test::ShownView;

namespace {

bool insideViewport(const ShownView& v, const QPointF& scenePoint) {
  return v.view.viewport()->rect().contains(v.view.mapFromScene(scenePoint));
}

}  // namespace

TEST_CASE("the first show fits the whole cycle into the view", "[canvas][navigation]") {
  ShownView v;
  const QRectF bounds = v.scene().contentBounds();
  CHECK(insideViewport(v, bounds.topLeft()));
  CHECK(insideViewport(v, bounds.bottomRight()));
  // Tight: the drawing fills most of one direction.
  const QRect onScreen = v.view.mapFromScene(bounds).boundingRect();
  CHECK(std::max(onScreen.width() / 800.0, onScreen.height() / 600.0) > 0.75);
  // y up: a point above the frame line is drawn higher on screen.
  CHECK(v.view.mapFromScene(QPointF(0.0, 10.0)).y() < v.view.mapFromScene(QPointF(0.0, 0.0)).y());
}

TEST_CASE("the wheel zooms about the cursor", "[canvas][navigation]") {
  ShownView v;
  const QPoint cursor(600, 200);
  const QPointF under = v.view.mapToScene(cursor);
  const double before = v.view.pixelsPerUnit();
  v.wheel(cursor, 3);
  CHECK(v.view.pixelsPerUnit() == Approx(before * std::pow(1.2, 3)));
  const QPoint after = v.view.mapFromScene(under);
  CHECK(std::abs(after.x() - cursor.x()) <= 1);
  CHECK(std::abs(after.y() - cursor.y()) <= 1);
  v.wheel(cursor, -3);
  CHECK(v.view.pixelsPerUnit() == Approx(before));
}

TEST_CASE("dragging the background pans the view and edits nothing", "[canvas][navigation]") {
  ShownView v;
  const QPoint from(20, 20);
  const QPointF grabbed = v.view.mapToScene(from);
  v.drag(from, QPoint(120, 70));
  const QPoint now = v.view.mapFromScene(grabbed);
  CHECK(std::abs(now.x() - 120) <= 1);
  CHECK(std::abs(now.y() - 70) <= 1);
  CHECK(v.document.undoStack()->count() == 0);
}

TEST_CASE("a document reset fits the new design, whatever its size", "[canvas][navigation]") {
  ShownView v;
  k::Design metres = k::fourBarDesign({0.06, 0.025, 0.07, 0.045}, k::Branch::Open, "m").value();
  v.wheel(QPoint(400, 300), -5);  // the user had zoomed out
  v.document.reset(metres);
  for (const auto id : {fourbar::kO2, fourbar::kO4, fourbar::kB, fourbar::kC}) CHECK(insideViewport(v, v.point(id)));
  CHECK(v.view.pixelsPerUnit() > 1000.0);  // ~0.13 m across ~500 px

  SECTION("fitToView brings back a drawing panned out of sight") {
    v.drag(QPoint(5, 5), QPoint(795, 595));
    v.drag(QPoint(5, 5), QPoint(795, 595));
    CHECK_FALSE(insideViewport(v, v.point(fourbar::kO4)));
    v.view.fitToView();
    CHECK(insideViewport(v, v.point(fourbar::kO4)));
  }
}

TEST_CASE("in presentation mode a narrow canvas still gives the drawing most of its width", "[canvas][navigation]") {
  // At presentation scale the margin for the larger pins is 80 px a side: on a 240 px wide
  // canvas (an 800 px window beside its charts) that left the linkage 80 px.
  ShownView v;
  v.view.setPresentationScale(2.0);
  v.view.resize(240, 700);
  QCoreApplication::processEvents();
  v.view.fitToView();
  const QRect onScreen = v.view.mapFromScene(v.scene().contentBounds()).boundingRect();
  CHECK(onScreen.width() >= 0.6 * v.view.viewport()->width());
  CHECK(v.view.viewport()->rect().contains(onScreen));
}
