// A refusal belongs to the design it was made for (ui/panels/refusal_label.h). A new user typed
// 5 into Coupler and then 5 into Rocker, was told the lengths cannot be assembled, and kept
// that red sentence through undo, another example, File ▸ New and File ▸ Open, on linkages
// that have no rocker. Typed into the real window, then each way of replacing the design.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/motion_panel.h"

#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <string>

using namespace linkwright;

namespace {

// Coupler 5 is accepted (the crank can still reach part of its turn); rocker 5 then cannot
// be assembled anywhere and is refused.
void provokeRefusal(test::Journey& journey) {
  ui::DimensionsPanel* panel = journey.window().dimensionsPanel();
  journey.type(panel->editor(kinematics::ParameterSlot::CouplerLength), "5");
  journey.check("Coupler 5");
  journey.type(panel->editor(kinematics::ParameterSlot::RockerLength), "5");
  REQUIRE(panel->refusalMessage().contains("Not applied"));
  journey.expectRefusal();
  journey.check("Rocker 5, refused");
}

}  // namespace

TEST_CASE("a refused length's message goes when the design it was about goes", "[ui][window][journey][refusal]") {
  test::Journey journey(QSize(1366, 768));
  provokeRefusal(journey);
  const std::string how = GENERATE("undo", "another example", "new", "open");
  CAPTURE(how);
  QTemporaryDir dir;
  const QString path = dir.filePath("arm.linkwright");
  // Coupler 5 was applied: replacing the design asks first, and the user discards it.
  if (how != "undo")
    journey.whenDialogOpens<QMessageBox>([](QMessageBox* ask) { ask->button(QMessageBox::Discard)->click(); });
  if (how == "undo") {
    journey.key(Qt::Key_Z, Qt::ControlModifier);
  } else if (how == "another example") {
    journey.example("excavator-boom");
  } else if (how == "new") {
    journey.menu({"File", "New", "Four-bar"});
  } else {
    ui::MainWindow other;
    other.newDocument(*kinematics::designForExample("seed-arm"));
    REQUIRE(other.saveTo(path));
    journey.answerFileDialog(path);
    journey.menu({"File", "Open"});
    REQUIRE(journey.window().document()->filePath() == path);
  }
  CHECK(journey.window().dimensionsPanel()->refusalMessage().isEmpty());
  journey.check(how);
}

TEST_CASE("a refusal stays while its design stays", "[ui][window][journey][refusal]") {
  test::Journey journey;
  provokeRefusal(journey);
  // Moving the crank or changing the plots does not replace the design.
  QTest::mouseClick(journey.window().motionPanel()->playButton(), Qt::LeftButton);
  QTest::qWait(100);
  QTest::mouseClick(journey.window().motionPanel()->playButton(), Qt::LeftButton);
  CHECK(journey.window().dimensionsPanel()->refusalMessage().contains("cannot"));
  journey.expectRefusal();
  journey.check("Play, pause");
}
