// The window on the screens people have: a 1366×768 laptop and a 1024×768 projector (the
// journeys' runner has both, journeys/screens.json). The window opens inside each, and after
// every step, on every tab and in presentation mode, it is still inside, and every label,
// button, input, axis title and legend entry is whole: masses and gravity can still be typed.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/panels/dynamics_panel.h"
#include "ui/panels/mass_table.h"

#include "kinematics/design/design.h"
#include "tests/support/catch.h"

#include <QApplication>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QTabWidget>
#include <QTest>

using namespace linkwright;

namespace {

// Double-clicks the cell, types `text` and Return, as a person edits a table cell.
void typeInCell(test::Journey& journey, QTableWidget* table, int row, int column, const QString& text) {
  table->scrollToItem(table->item(row, column));
  const QRect cell = table->visualRect(table->model()->index(row, column));
  REQUIRE(table->viewport()->rect().contains(cell.center()));
  QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
  QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell.center());
  QWidget* editor = QApplication::focusWidget();
  REQUIRE(editor != nullptr);
  QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
  QTest::keyClicks(editor, text);
  QTest::keyClick(editor, Qt::Key_Return);
  journey.settle();
}

QTabWidget* analysisTabs(ui::MainWindow& window) {
  auto* tabs = window.findChild<QTabWidget*>(QStringLiteral("AnalysisTabs"));
  REQUIRE(tabs != nullptr);
  return tabs;
}

// Every tab of the right-hand pane, as a click on it.
void everyTab(test::Journey& journey, const std::string& when) {
  QTabWidget* tabs = analysisTabs(journey.window());
  for (int i = 0; i < tabs->count(); ++i) {
    tabs->setCurrentIndex(i);
    journey.checkFitsScreen(when + ", tab " + tabs->tabText(i).toStdString());
  }
}

// The Forces tab: a mass typed in the Links table, gravity switched on and its value typed.
void typeMassAndGravity(test::Journey& journey, const std::string& when) {
  ui::MainWindow& window = journey.window();
  journey.menu({"View", "Forces and masses"});
  journey.checkFitsScreen(when + ", Forces tab");
  ui::DynamicsPanel* panel = window.findChild<ui::DynamicsPanel*>();
  REQUIRE(panel != nullptr);
  const QString mass = when == "normal" ? QStringLiteral("0.75") : QStringLiteral("0.5");
  typeInCell(journey, panel->linkTable(), 1, 1, mass);
  journey.checkFitsScreen(when + ", a mass typed");
  const auto& links = window.document()->design().dynamics.links;
  const auto coupler = std::find_if(links.begin(), links.end(), [](const auto& l) { return l.link == "coupler"; });
  REQUIRE(coupler != links.end());
  CHECK(coupler->mass == mass.toDouble());
  if (!panel->gravityBox()->isChecked())
    QTest::mouseClick(panel->gravityBox(), Qt::LeftButton, {}, QPoint(8, panel->gravityBox()->height() / 2));
  journey.settle();
  REQUIRE(panel->gravityBox()->isChecked());
  const QString g = when == "normal" ? QStringLiteral("9.81") : QStringLiteral("9.8");
  journey.type(panel->gravitySpin(), g);
  journey.checkFitsScreen(when + ", gravity typed");
  REQUIRE(window.document()->design().dynamics.loads.gravity.has_value());
  CHECK(window.document()->design().dynamics.loads.gravity->y() == Approx(-g.toDouble()));
}

}  // namespace

TEST_CASE(
    "on a 1366×768 laptop and a 1024×768 projector the window opens inside the screen, stays there on "
    "every tab and in presentation mode, and every control stays whole and usable",
    "[journey][screens]") {
  for (const char* name : {"laptop", "projector"}) {
    CAPTURE(name);
    test::Journey journey(test::journeyScreen(QString::fromLatin1(name)));
    journey.checkFitsScreen("opened");
    for (const char* example : {"funsho-fourbar", "ls3-engine", "excavator-boom"}) {
      journey.example(example);
      everyTab(journey, example);
    }
    journey.example("funsho-fourbar");
    typeMassAndGravity(journey, "normal");
    journey.menu({"View", "Presentation mode"});
    everyTab(journey, "presenting");
    typeMassAndGravity(journey, "presenting");
    journey.key(Qt::Key_F11);
    journey.checkFitsScreen("presentation left");
  }
}
