// The one dimensions editor as a person uses it: scroll to a number of any linkage, slide it
// with the mouse, undo it with Ctrl+Z; type a four-bar's named length, slide its coupler. After
// every step the journeys' invariants hold, and one slide is one undo step.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/parameter_editor.h"

#include "kinematics/design/design.h"
#include "kinematics/design/parameters.h"
#include "tests/support/catch.h"

#include <QDoubleSpinBox>
#include <QScrollArea>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QTest>
#include <QUndoStack>

#include <cmath>

using namespace linkwright;

namespace {

// Scrolls the side panel to `widget` (as a person scrolls to it) and returns the centre of
// the slider's handle in the slider's coordinates.
QPoint handleOf(ui::MainWindow& window, QSlider* slider) {
  window.findChild<QScrollArea*>("SidePanel")->ensureWidgetVisible(slider);
  QStyleOptionSlider option;
  option.initFrom(slider);
  option.orientation = slider->orientation();
  option.minimum = slider->minimum();
  option.maximum = slider->maximum();
  option.sliderPosition = slider->sliderPosition();
  option.sliderValue = slider->value();
  return slider->style()->subControlRect(QStyle::CC_Slider, &option, QStyle::SC_SliderHandle, slider).center();
}

// Presses the slider's handle, drags it `dx` pixels in steps and lets go.
void slide(test::Journey& journey, QSlider* slider, int dx) {
  const QPoint from = handleOf(journey.window(), slider);
  QTest::mousePress(slider, Qt::LeftButton, {}, from);
  for (int step = 1; step <= 5; ++step) QTest::mouseMove(slider, from + QPoint(dx * step / 5, 0));
  QTest::mouseRelease(slider, Qt::LeftButton, {}, from + QPoint(dx, 0));
}

}  // namespace

TEST_CASE("slide a six-bar's number with the mouse and undo it: one step", "[journey][dimensions]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.example("watt-ii");
  journey.check("Examples ▸ watt-ii");
  const kinematics::Design before = window.document()->design();
  ui::DimensionsPanel* panel = window.dimensionsPanel();
  // The last length of the linkage: the one a person finds at the bottom of the list.
  std::size_t last = 0;
  for (std::size_t i = 0; i < panel->fields().size(); ++i)
    if (panel->fields()[i].unit() == kinematics::ParameterUnit::Length) last = i;
  const double was = panel->editor(last)->value();
  slide(journey, panel->parameterEditor(last)->slider(), 12);
  CHECK(panel->editor(last)->value() > was);
  CHECK(kinematics::parameterValue(window.document()->mechanism(), panel->fields()[last].parameter) ==
        Approx(panel->editor(last)->value()).epsilon(1e-12));
  CHECK(window.document()->undoStack()->count() == 1);
  journey.check("slide " + panel->fields()[last].label.toStdString());
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(window.document()->design() == before);
  CHECK(panel->editor(last)->value() == was);
  journey.check("Ctrl+Z");
}

TEST_CASE("type a four-bar's named length, slide its coupler, undo both", "[journey][dimensions][fourbar]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  const kinematics::Design before = window.document()->design();
  ui::DimensionsPanel* panel = window.dimensionsPanel();
  journey.type(panel->editor(kinematics::ParameterSlot::RockerLength), "50");
  CHECK(window.document()->fourBar()->lengths.rocker == 50.0);
  journey.check("Rocker 50");
  const std::size_t coupler = *panel->fieldIndex(kinematics::ParameterSlot::CouplerLength);
  slide(journey, panel->parameterEditor(coupler)->slider(), -10);
  CHECK(window.document()->fourBar()->lengths.coupler < 70.0);
  CHECK(window.document()->undoStack()->count() == 2);
  journey.check("slide the coupler");
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(window.document()->design() == before);
  journey.check("Ctrl+Z twice");
}

TEST_CASE("lengthen the arm's path by typing its end: the whole path is analysed", "[journey][dimensions][arm]") {
  // Issue 57 item 8: the time base kept its old end, so 0.424 m of the longer path were analysed.
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.example("seed-arm");
  ui::DimensionsPanel* panel = window.dimensionsPanel();
  const auto endField = [panel](kinematics::ParameterSlot slot) {
    for (std::size_t i = 0; i < panel->fields().size(); ++i)
      if (panel->fields()[i].parameter.slot == slot && panel->fields()[i].parameter.vertex == 1)
        return panel->editor(i);
    FAIL("no field for the path's end");
    return static_cast<QDoubleSpinBox*>(nullptr);
  };
  journey.type(endField(kinematics::ParameterSlot::PathX), "-0.2");
  journey.check("path end x −0.2 m");
  journey.type(endField(kinematics::ParameterSlot::PathY), "0.4");
  journey.check("path end y 0.4 m");
  const kinematics::Design& d = window.document()->design();
  REQUIRE(d.time.has_value());
  const double length = std::sqrt(0.5 * 0.5 + 0.4 * 0.4);        // from (0.3, 0) to (−0.2, 0.4) m
  CHECK(d.time->toTime == Approx(length / 2.0).epsilon(1e-12));  // at the example's 2 m/s
  CHECK(window.document()->undoStack()->count() == 2);
}
