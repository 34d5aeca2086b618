// The mouse wheel over the side panel scrolls it and edits nothing (ui/wheel_guard.h): a new
// user scrolling past the Branch combo box flipped the linkage to its mirror image. Every
// spin box, combo box and slider of the real window's side panel is wheeled, on a four-bar and
// on a six-bar whose dimension fields are made anew, and the document must not change.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"

#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QScrollArea>
#include <QTest>
#include <QWheelEvent>

#include <string>
#include <vector>

using namespace linkwright;

namespace {

// The side panel's controls that a wheel could change, as a person sees them (visible ones).
std::vector<QWidget*> wheelableControls(QScrollArea* side) {
  std::vector<QWidget*> controls;
  for (QWidget* w : side->widget()->findChildren<QWidget*>()) {
    const bool takesWheel = qobject_cast<QAbstractSpinBox*>(w) != nullptr || qobject_cast<QComboBox*>(w) != nullptr ||
                            qobject_cast<QAbstractSlider*>(w) != nullptr;
    if (takesWheel && w->isVisibleTo(side) && w->isEnabled()) controls.push_back(w);
  }
  return controls;
}

// A notch of the wheel at the control's centre; returns whether the control kept the event.
bool wheel(QWidget* control, int notches) {
  const QPointF at = QPointF(control->rect().center());
  QWheelEvent event(at, control->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton, Qt::NoModifier,
                    Qt::NoScrollPhase, false);
  QApplication::sendEvent(control, &event);
  return event.isAccepted();
}

}  // namespace

TEST_CASE("the wheel over the side panel's controls edits nothing until a control has focus",
          "[ui][window][journey][wheel]") {
  const std::string example = GENERATE("thesis-crank-rocker", "watt-ii");
  CAPTURE(example);
  test::Journey journey(QSize(1366, 768));
  ui::MainWindow& window = journey.window();
  journey.example(example);
  auto* side = window.findChild<QScrollArea*>("SidePanel");
  REQUIRE(side != nullptr);
  const kinematics::Design before = window.document()->design();

  const std::vector<QWidget*> controls = wheelableControls(side);
  REQUIRE(controls.size() >= 5);
  for (QWidget* control : controls) {
    CAPTURE(control->metaObject()->className(), control->objectName().toStdString());
    // A click or Tab focuses it; the wheel must not, or the next notch would edit it.
    CHECK(control->focusPolicy() == Qt::StrongFocus);
    CHECK_FALSE(wheel(control, -1));  // left for the scroll area
    CHECK_FALSE(wheel(control, 1));
  }
  QApplication::processEvents();
  CHECK(window.document()->undoStack()->count() == 0);
  CHECK(window.document()->design() == before);
  journey.check("the wheel over every control");
}

TEST_CASE("a focused control in the side panel still takes the wheel", "[ui][window][journey][wheel]") {
  test::Journey journey(QSize(1366, 768));
  ui::MainWindow& window = journey.window();
  auto* side = window.findChild<QScrollArea*>("SidePanel");
  REQUIRE(side != nullptr);
  QAbstractSlider* slider = side->widget()->findChild<QAbstractSlider*>();
  REQUIRE(slider != nullptr);
  const int value = slider->value();
  slider->setFocus(Qt::MouseFocusReason);
  REQUIRE(slider->hasFocus());
  CHECK(wheel(slider, 1));
  CHECK(slider->value() != value);
}
