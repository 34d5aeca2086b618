// The side panels: typing a length goes through the document and shows the core's Grashof
// class; a refused value snaps back and says why; the animator rocks a non-Grashof crank.

#include "ui/animation/crank_animator.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/length_editor.h"
#include "ui/panels/motion_panel.h"
#include "ui/settings.h"

#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"

#include "tests/support/catch.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QTest>

using namespace linkwright;

namespace {

QDoubleSpinBox* spinOf(ui::LengthEditor* editor) { return editor->findChild<QDoubleSpinBox*>(); }

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
  typeInto(spinOf(lengths.lengthEditor(0)), 20.0);  // 20 + 70 > 25 + 45: non-Grashof
  CHECK(doc.fourBar()->lengths.frame == 20.0);
  CHECK(doc.analysis().grashof->category == kinematics::GrashofClass::TripleRocker);
  CHECK(analysis.grashofText().contains("Triple-rocker"));
  doc.undoStack()->undo();
  CHECK(doc.fourBar()->lengths.frame == 60.0);
  CHECK(spinOf(lengths.lengthEditor(0))->value() == 60.0);
}

TEST_CASE("a length that cannot be assembled is refused, shown, and the editor snaps back", "[ui][panels][errors]") {
  ui::MechanismDocument doc;
  ui::DimensionsPanel lengths(&doc);
  lengths.show();
  const kinematics::Design before = doc.design();
  typeInto(spinOf(lengths.lengthEditor(0)), 900.0);
  CHECK(doc.design() == before);
  CHECK(lengths.refusalMessage().contains("cannot be assembled at any crank angle"));
  CHECK(spinOf(lengths.lengthEditor(0))->value() == 60.0);
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
