// Springs as a person adds and edits them: on the excavator boom, View ▸ Forces and masses, two
// ends picked, Add spring, the stiffness typed in its cell, a negative one refused, Remove, and
// Ctrl+Z. After every step the journeys' invariants hold, and the design, the table and the
// canvas hold the same springs, never an earlier step's.

#include "tests/ui/journeys/journey.h"

#include "ui/canvas/linkage_scene.h"
#include "ui/canvas/linkage_view.h"
#include "ui/canvas/springs_item.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/analysis_panel.h"
#include "ui/panels/dynamics_panel.h"
#include "ui/panels/mass_table.h"
#include "ui/panels/springs_editor.h"

#include "kinematics/design/design.h"
#include "tests/support/catch.h"

#include <QComboBox>
#include <QInputDialog>
#include <QPushButton>
#include <QTest>
#include <QUndoStack>

using namespace linkwright;

namespace {

// Double-clicks the cell, types `text` and Return, as a person edits a table cell.
void typeInCell(test::Journey& journey, QTableWidget* table, int row, int column, const QString& text) {
  const QRect cell = table->visualRect(table->model()->index(row, column));
  QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
  QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell.center());
  QWidget* editor = QApplication::focusWidget();
  REQUIRE(editor != nullptr);
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(editor, text);
  QTest::keyClick(editor, Qt::Key_Return);
  journey.settle();
}

// The table and the canvas show the design's springs.
void checkShown(ui::MainWindow& window, ui::SpringsEditor* editor) {
  const auto& springs = window.document()->design().dynamics.loads.springs;
  CHECK(editor->table()->rowCount() == static_cast<int>(springs.size()));
  const auto* scene = dynamic_cast<const ui::LinkageScene*>(window.canvas()->linkageScene());
  REQUIRE(scene != nullptr);
  const auto* drawn = scene->springsItem();
  CHECK(drawn->ends().size() == springs.size());
  CHECK(drawn->isVisible() == !springs.empty());
}

}  // namespace

TEST_CASE("add a spring to the boom, type its stiffness, have a wrong one refused, remove it, undo",
          "[journey][forces][springs]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.example("excavator-boom");
  journey.menu({"View", "Forces and masses"});
  auto* editor = window.findChild<ui::SpringsEditor*>();
  REQUIRE(editor != nullptr);
  CHECK(editor->table()->rowCount() == 0);
  journey.check("the boom's Forces tab");

  editor->firstEndBox()->setCurrentIndex(editor->firstEndBox()->findText("C on boom"));
  editor->secondEndBox()->setCurrentIndex(editor->secondEndBox()->findText("A on the frame"));
  QTest::mouseClick(editor->addButton(), Qt::LeftButton);
  journey.settle();
  const kinematics::Design& d = window.document()->design();
  REQUIRE(d.dynamics.loads.springs.size() == 1);
  const kinematics::Spring& s = d.dynamics.loads.springs.front();
  CHECK(s.first == kinematics::SpringEnd{"boom", "C"});
  CHECK(s.second == kinematics::SpringEnd{"", "A"});
  CHECK(s.stiffness == ui::SpringsEditor::kNewStiffness);
  const auto& at = window.document()->pose().position;
  CHECK(s.freeLength == Approx((at[d.mechanism.findPoint("C")->index] - at[d.mechanism.findPoint("A")->index]).norm()));
  CHECK(editor->table()->item(0, 0)->text() == "spring: C on boom → A on the frame");
  // Edit ▸ Undo names the step by the spring's ends ("Undo Add spring spring" before).
  CHECK(window.document()->undoStack()->undoText() == "Add a spring from C to A");
  checkShown(window, editor);
  journey.check("Add spring");

  typeInCell(journey, editor->table(), 0, 1, "5000");
  CHECK(window.document()->design().dynamics.loads.springs.front().stiffness == 5000.0);
  checkShown(window, editor);
  journey.check("stiffness typed");

  typeInCell(journey, editor->table(), 0, 1, "-3");
  CHECK(window.document()->design().dynamics.loads.springs.front().stiffness == 5000.0);  // nothing changed
  CHECK(window.findChild<ui::DynamicsPanel*>()->refusalMessage().contains("stiffness"));
  CHECK(editor->table()->item(0, 1)->text() == "5000");  // the cell shows the design again
  journey.expectRefusal();
  journey.check("a negative stiffness");

  QTest::mouseClick(editor->table()->viewport(), Qt::LeftButton, {},
                    editor->table()->visualRect(editor->table()->model()->index(0, 1)).center());
  REQUIRE(editor->removeButton()->isEnabled());
  QTest::mouseClick(editor->removeButton(), Qt::LeftButton);
  journey.settle();
  CHECK(window.document()->design().dynamics.loads.springs.empty());
  CHECK(window.findChild<ui::DynamicsPanel*>()->refusalMessage().isEmpty());  // no stale refusal
  checkShown(window, editor);
  journey.check("Remove");

  journey.key(Qt::Key_Z, Qt::ControlModifier);
  REQUIRE(window.document()->design().dynamics.loads.springs.size() == 1);
  CHECK(window.document()->design().dynamics.loads.springs.front().stiffness == 5000.0);
  checkShown(window, editor);
  journey.check("Ctrl+Z");
}

TEST_CASE(
    "Edit ▸ Balance the torque by a spring leaves the four-bar a four-bar: its Grashof class, time ratio "
    "and rocker limits stay",
    "[journey][forces][springs]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.example("funsho-fourbar");
  journey.check("funsho-fourbar");
  const QString grashof = window.analysisPanel()->grashofText();
  const QString ratio = window.analysisPanel()->timeRatioText();
  REQUIRE(grashof.contains(QStringLiteral("Crank-rocker")));
  // The link the spring's moving end goes on: the dialog's first, the crank.
  journey.acceptDialog<QInputDialog>();
  journey.menu({"Edit", "Balance the torque by a spring"});
  journey.check("balanced by a spring");
  REQUIRE(window.document()->design().dynamics.loads.springs.size() == 1);
  // The spring's ends are points of the mechanism, one on the crank; the linkage is what it was.
  CHECK(window.analysisPanel()->grashofText() == grashof);
  CHECK(window.analysisPanel()->timeRatioText() == ratio);
  CHECK(window.document()->fourBar().has_value());
}
