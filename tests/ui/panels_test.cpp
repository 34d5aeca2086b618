// The side panels: typing a length goes through the document and shows the core's Grashof
// class; a refused value snaps back and says why; the animator rocks a non-Grashof crank.

#include "ui/animation/crank_animator.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/motion_panel.h"
#include "ui/panels/parameter_editor.h"
#include "ui/settings.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/design/parameters.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSlider>
#include <QTest>

#include <algorithm>

using namespace linkwright;

namespace {

void typeInto(QDoubleSpinBox* spin, double value) {
  spin->setFocus();
  spin->selectAll();
  QTest::keyClicks(spin, QString::number(value));
  QTest::keyClick(spin, Qt::Key_Return);
}

}  // namespace

TEST_CASE("typing a length changes the design and the Grashof badge as the core says", "[ui][panels]") {
  ui::MechanismDocument doc;
  ui::DimensionsPanel lengths(&doc);
  ui::AnalysisPanel analysis(&doc);
  CHECK(analysis.grashofText().contains("Crank-rocker"));
  typeInto(lengths.editor(kinematics::ParameterSlot::FrameLength), 20.0);  // 20 + 70 > 25 + 45: non-Grashof
  CHECK(doc.fourBar()->lengths.frame == 20.0);
  CHECK(doc.analysis().grashof->category == kinematics::GrashofClass::TripleRocker);
  CHECK(analysis.grashofText().contains("Triple-rocker"));
  doc.undoStack()->undo();
  CHECK(doc.fourBar()->lengths.frame == 60.0);
  CHECK(lengths.editor(kinematics::ParameterSlot::FrameLength)->value() == 60.0);
}

TEST_CASE("a length that cannot be assembled is refused, shown, and the editor snaps back", "[ui][panels][errors]") {
  ui::MechanismDocument doc;
  ui::DimensionsPanel lengths(&doc);
  lengths.show();
  const kinematics::Design before = doc.design();
  typeInto(lengths.editor(kinematics::ParameterSlot::FrameLength), 900.0);
  CHECK(doc.design() == before);
  CHECK(lengths.refusalMessage().contains("cannot be assembled at any crank angle"));
  CHECK(lengths.editor(kinematics::ParameterSlot::FrameLength)->value() == 60.0);
}

TEST_CASE("the branch box switches the assembly branch, undoably", "[ui][panels]") {
  ui::MechanismDocument doc;
  ui::CrankAnimator animator(&doc);
  ui::MotionPanel motion(&doc, &animator);
  motion.branchBox()->setCurrentIndex(1);
  CHECK(doc.fourBar()->branch == kinematics::Branch::Crossed);
  doc.undoStack()->undo();
  CHECK(doc.fourBar()->branch == kinematics::Branch::Open);
  CHECK(motion.branchBox()->currentIndex() == 0);
}

TEST_CASE("a non-Grashof crank rocks between the ends of its range", "[ui][animation]") {
  ui::MechanismDocument doc;
  kinematics::Design d = testing::withLengths(doc.design(), {40, 30, 20, 25});  // |θ2| ≤ 78.58°
  d.omega = 1.0;
  REQUIRE_FALSE(doc.edit(d, "lengths").has_value());
  ui::CrankAnimator animator(&doc);
  double highest = -10.0;
  bool turnedBack = false;
  for (int frame = 0; frame < 400; ++frame) {
    animator.advance(0.016);
    highest = std::max(highest, doc.crankAngle());
    turnedBack = turnedBack || animator.direction() < 0;
    CHECK(doc.analysis().inputRange.contains(doc.crankAngle(), 1e-9));
  }
  CHECK(turnedBack);
  CHECK(kinematics::radToDeg(highest) == Approx(78.5848).margin(1e-3));
}

TEST_CASE("stepping moves the crank by the chosen angle", "[ui][animation]") {
  ui::MechanismDocument doc;
  ui::CrankAnimator animator(&doc);
  animator.stepForward();
  CHECK(kinematics::radToDeg(doc.crankAngle()) == Approx(30.0));
  animator.setStepAngle(kinematics::degToRad(10.0));
  animator.stepBackward();
  CHECK(kinematics::radToDeg(doc.crankAngle()) == Approx(20.0));
}

TEST_CASE("a linear input on a grid is moved, stepped and named in its length unit", "[ui][panels][driven]") {
  ui::MechanismDocument doc;
  kinematics::Design boom = *kinematics::designForExample("excavator-boom");
  boom.time.reset();  // its grid: the cylinder from 1.2 to 1.9 m
  doc.reset(boom);
  ui::CrankAnimator animator(&doc);
  ui::MotionPanel motion(&doc, &animator);
  CHECK(motion.stepBox()->suffix() == " m");
  CHECK(motion.stepBox()->value() == Approx(0.07));  // a tenth of the grid
  motion.positionSlider()->setValue(ui::MotionPanel::kTimeSliderSteps / 2);
  CHECK(doc.crankAngle() == Approx(1.55).epsilon(1e-12));
  CHECK(motion.positionText() == "Actuator A–C length = 1.55 m");
  animator.stepForward();
  CHECK(doc.crankAngle() == Approx(1.62).epsilon(1e-12));
  CHECK(doc.analysis().inputRange.ranges.size() == 1);
  CHECK_FALSE(doc.analysis().inputRange.fullRotation);
}

TEST_CASE("one dimensions editor: every number of every example has a spin box and a slider that spans it",
          "[ui][panels][dimensions]") {
  ui::MechanismDocument doc;
  ui::DimensionsPanel panel(&doc);
  for (const kinematics::Example& e : kinematics::examples()) {
    CAPTURE(e.name);
    doc.reset(kinematics::designFromExample(e));
    const auto parameters = kinematics::parametersOf(doc.mechanism());
    REQUIRE(panel.fields().size() == parameters.size());
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      CAPTURE(panel.fields()[i].label.toStdString());
      CHECK(panel.fields()[i].parameter == parameters[i]);
      CHECK_FALSE(panel.fields()[i].label.isEmpty());
      QSlider* slider = panel.parameterEditor(i)->slider();
      // The slider shows the value strictly inside its span, so it can move either way.
      CHECK(slider->value() > slider->minimum());
      CHECK(slider->value() < slider->maximum());
    }
  }
}

TEST_CASE("a four-bar's named length and any linkage's number: a slider drag is one undo step",
          "[ui][panels][dimensions][undo]") {
  ui::MechanismDocument doc;
  ui::DimensionsPanel panel(&doc);
  const auto drag = [&](std::size_t field) {
    QSlider* slider = panel.parameterEditor(field)->slider();
    const int start = slider->value();
    slider->setSliderDown(true);
    for (int step = 1; step <= 5; ++step) slider->setValue(start + 4 * step);
    slider->setSliderDown(false);  // released: the edit is complete
  };
  SECTION("the four-bar's coupler, through the core's one path") {
    const kinematics::Design before = doc.design();
    const std::size_t coupler = *panel.fieldIndex(kinematics::ParameterSlot::CouplerLength);
    drag(coupler);
    REQUIRE(doc.undoStack()->count() == 1);
    const double typed = panel.editor(coupler)->value();
    CHECK(doc.fourBar()->lengths.coupler == Approx(typed).epsilon(1e-12));
    CHECK(doc.fourBar()->lengths.coupler > 70.0);  // moved up the slider, and still a four-bar
    CHECK(doc.mechanism() == kinematics::withFourBarLengths(before.mechanism, *kinematics::asFourBar(before.mechanism),
                                                            doc.fourBar()->lengths));
    doc.undoStack()->undo();
    CHECK(doc.design() == before);
    // A second drag of the same field is its own undo step.
    drag(coupler);
    drag(coupler);
    CHECK(doc.undoStack()->count() == 2);
  }
  SECTION("the engine's rod, a slider-crank's number that had no slider before") {
    doc.reset(*kinematics::designForExample("ls3-engine"));
    const kinematics::Design before = doc.design();
    const auto& fields = panel.fields();
    const auto rod = std::find_if(fields.begin(), fields.end(), [](const ui::DimensionField& f) {
      return f.parameter.slot == kinematics::ParameterSlot::Length && f.label.startsWith("to ");
    });
    REQUIRE(rod != fields.end());
    const auto index = static_cast<std::size_t>(rod - fields.begin());
    drag(index);
    REQUIRE(doc.undoStack()->count() == 1);
    CHECK(doc.design() != before);
    CHECK(kinematics::parameterValue(doc.mechanism(), rod->parameter) ==
          Approx(panel.editor(index)->value()).epsilon(1e-12));
    doc.undoStack()->undo();
    CHECK(doc.design() == before);
  }
}

TEST_CASE("a four-bar's point on the coupler is added and removed from the one editor", "[ui][panels][dimensions]") {
  ui::MechanismDocument doc;
  doc.reset(*kinematics::fourBarDesign(kinematics::kThesisCrankRocker));
  ui::DimensionsPanel panel(&doc);
  REQUIRE_FALSE(kinematics::couplerPointOf(doc.mechanism(), *doc.fourBar()));
  CHECK_FALSE(panel.fieldIndex(kinematics::ParameterSlot::Along));
  panel.couplerPointBox()->setChecked(true);
  const auto point = kinematics::couplerPointOf(doc.mechanism(), *doc.fourBar());
  REQUIRE(point);
  CHECK(point->spec.along == 35.0);  // the coupler's middle
  REQUIRE(panel.fieldIndex(kinematics::ParameterSlot::Along));
  CHECK(panel.fields()[*panel.fieldIndex(kinematics::ParameterSlot::Along)].label == "along B→C");
  panel.couplerPointBox()->setChecked(false);
  CHECK_FALSE(kinematics::couplerPointOf(doc.mechanism(), *doc.fourBar()));
  CHECK(doc.undoStack()->count() == 2);
}
