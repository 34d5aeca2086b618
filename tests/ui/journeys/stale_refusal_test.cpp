// A refusal belongs to the design it was made for (ui/panels/refusal_label.h). A new user typed
// 5 into Coupler and then 5 into Rocker, was told the lengths cannot be assembled, and kept
// that red sentence through undo, another example, File ▸ New and File ▸ Open, on linkages
// that have no rocker. Typed into the real window, then each way of replacing the design.

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/panels/length_editor.h"

#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QDoubleSpinBox>
#include <QTemporaryDir>
#include <QTest>

#include <string>

using namespace linkwright;

namespace {

void typeInto(QDoubleSpinBox* spin, const QString& text) {
  spin->setFocus();
  spin->selectAll();
  QTest::keyClicks(spin, text);
  QTest::keyClick(spin, Qt::Key_Return);
}

// Coupler 5 is accepted (the crank can still reach part of its turn); rocker 5 then cannot
// be assembled anywhere and is refused.
void provokeRefusal(ui::MainWindow& window) {
  ui::DimensionsPanel* panel = window.dimensionsPanel();
  typeInto(panel->lengthEditor(2)->findChild<QDoubleSpinBox*>(), "5");
  typeInto(panel->lengthEditor(3)->findChild<QDoubleSpinBox*>(), "5");
  REQUIRE(panel->refusalMessage().contains("Not applied"));
}

}  // namespace

TEST_CASE("a refused length's message goes when the design it was about goes", "[ui][window][journey][refusal]") {
  ui::MainWindow window;
  window.resize(1366, 768);
  window.show();
  REQUIRE(QTest::qWaitForWindowExposed(&window));
  provokeRefusal(window);
  const std::string how = GENERATE("undo", "another example", "new", "open");
  CAPTURE(how);
  QTemporaryDir dir;
  const QString path = dir.filePath("arm.linkwright");
  if (how == "undo") {
    window.document()->undoStack()->undo();
  } else if (how == "another example") {
    window.newDocument(*kinematics::designForExample("excavator-boom"));
  } else if (how == "new") {
    window.newDocument(*kinematics::designForExample("thesis-crank-rocker"));
  } else {
    ui::MainWindow other;
    other.newDocument(*kinematics::designForExample("seed-arm"));
    REQUIRE(other.saveTo(path));
    REQUIRE(window.openFile(path));
  }
  CHECK(window.dimensionsPanel()->refusalMessage().isEmpty());
}

TEST_CASE("a refusal stays while its design stays", "[ui][window][journey][refusal]") {
  ui::MainWindow window;
  provokeRefusal(window);
  // Moving the crank or changing the plots does not replace the design.
  window.document()->setCrankAngle(1.0);
  CHECK(window.dimensionsPanel()->refusalMessage().contains("cannot"));
}
