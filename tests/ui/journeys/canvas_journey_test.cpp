// The canvas as a person uses it: every example opened from the Examples menu is fitted with its
// labels inside the canvas; a joint dragged with the mouse and undone with Ctrl+Z leaves the
// design, the read-outs and the fit as they were.

#include "tests/ui/journeys/journey.h"

#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/dimensions_panel.h"

#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QDoubleSpinBox>
#include <QTest>
#include <QUndoStack>

using namespace linkwright;

TEST_CASE("each example from the menu is fitted, labels inside the canvas", "[journey][canvas]") {
  test::Journey journey;
  for (const kinematics::Example& e : kinematics::examples()) {
    journey.example(e.name);
    journey.expectFitted();
    journey.check("Examples ▸ " + e.name);
  }
  // And in View ▸ Instant centres: the centres' labels too.
  journey.menu({"View", "Instant centres and centrodes"});
  for (const char* name : {"thesis-crank-rocker", "shaper", "ls3-engine", "watt-ii"}) {
    journey.example(name);
    journey.menu({"View", "Fit to view"});
    journey.expectFitted();
    journey.check(std::string("centres, Examples ▸ ") + name + ", View ▸ Fit to view");
  }
}

TEST_CASE("a joint dragged with the mouse, then Ctrl+Z: the design and the view as before", "[journey][canvas]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  const kinematics::Design before = window.document()->design();
  const auto& fourBar = window.document()->fourBar();
  REQUIRE(fourBar);
  ui::LinkageView* view = window.canvas();
  const Eigen::Vector2d c = window.document()->pose().position[fourBar->c.index];
  const QPoint from = view->mapFromScene(QPointF(c.x(), c.y()));
  QTest::mousePress(view->viewport(), Qt::LeftButton, Qt::NoModifier, from);
  for (int step = 1; step <= 5; ++step) {
    QMouseEvent move(QEvent::MouseMove, QPointF(from + QPoint(6 * step, -4 * step)),
                     view->viewport()->mapToGlobal(QPointF(from + QPoint(6 * step, -4 * step))), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(view->viewport(), &move);
  }
  QTest::mouseRelease(view->viewport(), Qt::LeftButton, Qt::NoModifier, from + QPoint(30, -20));
  journey.settle();
  CHECK_FALSE(window.document()->design() == before);
  CHECK(window.document()->isModified());
  journey.check("drag C");
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(window.document()->design() == before);
  CHECK_FALSE(window.document()->isModified());
  journey.expectFitted();
  journey.check("Ctrl+Z");
}

TEST_CASE("a crank that cannot turn: its reach is labelled inside the canvas, centres apart from the joints",
          "[journey][canvas]") {
  test::Journey journey;
  ui::DimensionsPanel* panel = journey.window().dimensionsPanel();
  // Coupler 30: the crank of the thesis four-bar only rocks (S + L = 85 > P + Q = 75).
  journey.type(panel->editor(kinematics::ParameterSlot::CouplerLength), "30");
  REQUIRE_FALSE(journey.window().document()->analysis().inputRange.fullRotation);
  journey.check("Coupler 30");
  journey.menu({"View", "Fit to view"});
  journey.expectFitted();
  journey.check("View ▸ Fit to view");
  journey.menu({"View", "Instant centres and centrodes"});
  journey.menu({"View", "Fit to view"});
  journey.expectFitted();
  journey.check("View ▸ Instant centres, Fit to view");
}
