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
#include <functional>
#include <string>

using namespace linkwright;

namespace {

// `step` on a 1366×768 laptop and a 1024×768 projector, normal and then presenting; `where` names
// the screen and the mode.
void onEachScreen(const std::function<void(test::Journey&, const std::string& where)>& step) {
  for (const char* screen : {"laptop", "projector"}) {
    CAPTURE(screen);
    test::Journey journey(test::journeyScreen(QString::fromLatin1(screen)));
    for (const bool presenting : {false, true}) {
      if (presenting) journey.menu({"View", "Presentation mode"});
      step(journey, std::string(screen) + (presenting ? ", presenting" : ""));
    }
  }
}

}  // namespace

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

TEST_CASE("on a laptop and a projector, normal and presenting, Ctrl+0 keeps every canvas label inside",
          "[journey][canvas][screens]") {
  // Issue 57 item 4: labels keep their pixel size, so a fit of the drawing alone cut "crank can
  // reach…" and the arm's "outside s…" at the canvas's edge on the smaller screens.
  onEachScreen([](test::Journey& journey, const std::string& where) {
    for (const kinematics::Example& e : kinematics::examples()) {
      journey.example(e.name);
      journey.key(Qt::Key_0, Qt::ControlModifier);
      journey.expectFitted();
      journey.check(where + ", Examples ▸ " + e.name + ", Ctrl+0");
    }
    // A crank that only rocks, labelled with its reach.
    journey.example("thesis-crank-rocker");
    journey.type(journey.window().dimensionsPanel()->editor(kinematics::ParameterSlot::CouplerLength), "30");
    journey.key(Qt::Key_0, Qt::ControlModifier);
    journey.expectFitted();
    journey.check(where + ", coupler 30, Ctrl+0");
    journey.key(Qt::Key_Z, Qt::ControlModifier);  // unmodified again: the next example asks nothing
    // An arm's path partly out of reach, labelled with the stretch.
    journey.example("seed-arm");
    ui::DimensionsPanel* panel = journey.window().dimensionsPanel();
    for (std::size_t i = 0; i < panel->fields().size(); ++i)
      if (panel->fields()[i].parameter.slot == kinematics::ParameterSlot::PathY &&
          panel->fields()[i].parameter.vertex == 1)
        journey.type(panel->editor(i), "0.6");
    journey.key(Qt::Key_0, Qt::ControlModifier);
    journey.expectFitted();
    journey.check(where + ", arm's path end at y 0.6 m, Ctrl+0");
    journey.key(Qt::Key_Z, Qt::ControlModifier);
  });
}

TEST_CASE("on a laptop and a projector, force arrows that come after the fit have their labels inside",
          "[journey][canvas][screens]") {
  // The canvas was fitted before the forces landed, so the arrows' magnitudes ran past its edge
  // (presentation mode on the projector: "415 N" cut at the left) until Ctrl+0.
  onEachScreen([](test::Journey& journey, const std::string& where) {
    journey.example("funsho-fourbar");
    journey.menu({"View", "Force arrows"});
    journey.expectFitted();
    journey.check(where + ", View ▸ Force arrows");
    journey.menu({"View", "Force arrows"});  // off again for the next round
  });
}
