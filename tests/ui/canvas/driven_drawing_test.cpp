// What the canvas draws for linkages driven other than by a crank: a driven point's path, the
// stretches of it a two-link arm cannot reach with the times the tip is there, the arm's
// workspace annulus, and a cylinder from an actuator's base to its end.

#include "canvas_test_support.h"

#include "ui/canvas/actuator_item.h"
#include "ui/canvas/driven_path_item.h"
#include "ui/canvas/mechanism_items.h"
#include "ui/canvas/workspace_item.h"

#include "kinematics/design/parameters.h"

#include <QGraphicsLineItem>

#include "tests/support/catch.h"

namespace k = linkwright::kinematics;
using linkwright::ui::test::ShownView;

TEST_CASE("the arm's canvas shows its tip's path and its workspace", "[canvas][driven]") {
  ShownView v(*k::designForExample("seed-arm"));
  const auto& plan = v.scene().plan();
  REQUIRE(plan.drivenPaths.size() == 1);
  REQUIRE(plan.workspaces.size() == 1);
  const auto& items = v.scene().mechanismItems();
  // The annulus between |0.3 − 0.2| and 0.3 + 0.2 m about the shoulder.
  CHECK(items.workspace(0)->path().boundingRect().toRect() == QRectF(-0.5, -0.5, 1.0, 1.0).toRect());
  CHECK(items.workspace(0)->path().contains(QPointF(0.3, 0.0)));
  CHECK_FALSE(items.workspace(0)->path().contains(QPointF(0.05, 0.0)));
  const QPainterPath path = items.drivenPath(0)->path();
  CHECK(path.elementAt(0).x == 0.3);
  CHECK(path.elementAt(path.elementCount() - 1).y == 0.3);
  CHECK(items.drivenPath(0)->stretchLabels().empty());  // the seed's line lies inside the workspace
}

TEST_CASE("a path leaving the arm's workspace is marked with when the tip is outside", "[canvas][driven]") {
  // arm --to-point 0.7,0 at 2 m/s: the tip is out of reach from t = 0.1 s to 0.2 s.
  k::Design d = *k::designForExample("seed-arm");
  k::setParameter(d.mechanism, {k::PointId{1}, k::ParameterSlot::PathX, 0, 1}, 0.7);
  k::setParameter(d.mechanism, {k::PointId{1}, k::ParameterSlot::PathY, 0, 1}, 0.0);
  d.time->toTime = 0.2;
  ShownView v(d);
  REQUIRE(v.document.design() == d);
  const auto labels = v.scene().mechanismItems().drivenPath(0)->stretchLabels();
  REQUIRE(labels.size() == 1);
  CHECK(labels[0] == QString("outside 0.1–0.2 s"));
}

TEST_CASE("an actuator is drawn as a cylinder from its base to its end", "[canvas][driven]") {
  ShownView v(*k::designForExample("excavator-boom"));
  const auto& plan = v.scene().plan();
  REQUIRE(plan.actuators.size() == 1);
  CHECK(plan.actuators[0].base == k::PointId{1});
  CHECK(plan.actuators[0].end == k::PointId{2});
  const linkwright::ui::ActuatorItem& cylinder = *v.scene().mechanismItems().actuator(0);
  const QPointF base = v.point(k::PointId{1});
  const QPointF end = v.point(k::PointId{2});
  CHECK(cylinder.rodLine() == QLineF(base, end));
  // The barrel from the base, 0.85 of the shortest stroke (1.2 m): the rod shows beyond it.
  CHECK(cylinder.barrelLine().p1() == base);
  CHECK(cylinder.barrelLine().length() == Approx(0.85 * 1.2).epsilon(1e-12));
}

TEST_CASE("dragging an end of the tip's path moves it, one undo step", "[canvas][driven][drag]") {
  ShownView v(*k::designForExample("seed-arm"));
  const linkwright::ui::DragHandle end{k::PointId{1}, 1};
  const auto at = v.scene().handlePosition(end);
  REQUIRE(at);
  CHECK(*at == QPointF(0.0, 0.3));
  const k::Design before = v.document.design();
  const QPointF target(0.05, 0.35);
  v.drag(v.pixelOf(*at), v.pixelOf(target));
  const auto& line =
      std::get<k::PolylinePath>(std::get<k::PathPoint>(v.document.mechanism().points[1].definition).path);
  // Within a pixel of where the pointer let go.
  const double pixel = 1.0 / v.view.transform().m11();
  CHECK((line.vertices[1] - Eigen::Vector2d(0.05, 0.35)).norm() < 2.0 * pixel);
  CHECK(line.vertices[0] == Eigen::Vector2d(0.3, 0.0));
  CHECK(*v.scene().handlePosition(end) == linkwright::ui::toQt(line.vertices[1]));
  CHECK(v.document.undoStack()->count() == 1);
  v.document.undoStack()->undo();
  CHECK(v.document.design() == before);
}
