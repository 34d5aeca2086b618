// Whole tasks through the real window, each step followed by the journeys' invariants: save,
// open and re-open a design; export every format; run the animation; synthesize a linkage and
// use it; compare another tool's table that carries a typo; and every example with every view.

#include "tests/ui/journeys/journey.h"

#include "ui/compare/compare_dialog.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/dimensions_panel.h"
#include "ui/plots/plot_panel.h"
#include "ui/synthesis/candidate_table.h"
#include "ui/synthesis/synthesis_panel.h"
#include "ui/synthesis/synthesis_preview_item.h"

#include "kinematics/compare/table_comparison.h"
#include "kinematics/design/examples.h"
#include "tests/support/catch.h"

#include <QDoubleSpinBox>
#include <QFile>
#include <QPushButton>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <fstream>

using namespace linkwright;

namespace {

QByteArray head(const QString& path, int bytes) {
  QFile file(path);
  return file.open(QIODevice::ReadOnly) ? file.read(bytes) : QByteArray();
}

}  // namespace

TEST_CASE("save a changed design, open another, open it again", "[journey][files]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  QTemporaryDir dir;
  const QString path = dir.filePath("lecture.linkwright");
  journey.type(window.dimensionsPanel()->editor(kinematics::ParameterSlot::CrankLength), "20");
  journey.check("Crank 20");
  CHECK(window.windowTitle().contains("*"));
  const kinematics::Design saved = window.document()->design();
  journey.answerFileDialog(path);
  journey.menu({"File", "Save As"});
  CHECK(QFile::exists(path));
  CHECK(window.windowTitle().startsWith("lecture.linkwright"));
  CHECK_FALSE(window.document()->isModified());
  journey.check("Save As lecture.linkwright");
  journey.example("shaper");
  journey.check("Examples ▸ shaper");
  journey.answerFileDialog(path);
  journey.menu({"File", "Open"});
  CHECK(window.document()->design() == saved);
  journey.check("Open lecture.linkwright");
  journey.example("seed-arm");
  journey.menu({"File", "Open Recent", QStringLiteral("lecture.linkwright")});
  CHECK(window.document()->design() == saved);
  journey.check("Open Recent ▸ lecture.linkwright");
}

TEST_CASE("Save As a name with a dot in it adds .linkwright", "[journey][files]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  QTemporaryDir dir;
  // A tolerance study's file named after its tolerance (issue 57: written as "0.0001").
  journey.answerFileDialog(dir.filePath("0.0001"));
  journey.menu({"File", "Save As"});
  CHECK(QFile::exists(dir.filePath("0.0001.linkwright")));
  CHECK_FALSE(QFile::exists(dir.filePath("0.0001")));
  CHECK(window.windowTitle().startsWith("0.0001.linkwright"));
  journey.check("Save As 0.0001");
  journey.answerFileDialog(dir.filePath("arm.json"));
  journey.menu({"File", "Save As"});
  CHECK(QFile::exists(dir.filePath("arm.json")));
  CHECK_FALSE(QFile::exists(dir.filePath("arm.json.linkwright")));
  journey.check("Save As arm.json");
}

TEST_CASE("export the table, the links, the animation and the report", "[journey][export]") {
  test::Journey journey;
  QTemporaryDir dir;
  journey.answerFileDialog(dir.filePath("table.csv"));
  journey.menu({"File", "Export", "Table as CSV"});
  CHECK(head(dir.filePath("table.csv"), 200).contains("crank_angle_deg"));
  journey.check("Export ▸ CSV");
  journey.acceptDialog<QDialog>();
  journey.answerFileDialog(dir.filePath("links.dxf"));
  journey.menu({"File", "Export", "Links as DXF"});
  CHECK(head(dir.filePath("links.dxf"), 80).contains("SECTION"));
  journey.check("Export ▸ DXF");
  journey.acceptDialog<QDialog>();
  journey.answerFileDialog(dir.filePath("turn.gif"));
  journey.menu({"File", "Export", "Animation"});
  CHECK(head(dir.filePath("turn.gif"), 6) == "GIF89a");
  journey.check("Export ▸ Animation");
  journey.acceptDialog<QDialog>();
  journey.answerFileDialog(dir.filePath("report.pdf"));
  journey.menu({"Report", "PDF"});
  CHECK(head(dir.filePath("report.pdf"), 5) == "%PDF-");
  journey.check("Report ▸ PDF");
}

TEST_CASE("Space plays the linkage and Space stops it", "[journey][animation]") {
  test::Journey journey;
  const double start = journey.window().document()->crankAngle();
  journey.key(Qt::Key_Space);
  QTest::qWait(300);
  journey.check("Space, playing");
  journey.key(Qt::Key_Space);
  const double stopped = journey.window().document()->crankAngle();
  CHECK(stopped != start);
  QTest::qWait(200);
  CHECK(journey.window().document()->crankAngle() == stopped);
  journey.check("Space, stopped");
}

TEST_CASE("synthesize a crank-rocker for a swing and use it", "[journey][synthesis]") {
  test::Journey journey;
  ui::MainWindow& window = journey.window();
  journey.window().findChild<QTabWidget*>("AnalysisTabs")->setCurrentIndex(2);
  ui::SynthesisPanel* synthesis = window.synthesisPanel();
  synthesis->setProblem(kinematics::SynthesisProblem::Swing);
  journey.settle();
  REQUIRE(synthesis->outcome().has_value());
  REQUIRE_FALSE(synthesis->outcome()->rows.empty());
  const kinematics::Mechanism chosen = synthesis->outcome()->rows.front().candidate.design.mechanism;
  journey.check("Synthesis ▸ rocker swing");
  QTest::mouseClick(synthesis->useButton(), Qt::LeftButton);
  journey.settle();
  CHECK(window.document()->mechanism() == chosen);
  CHECK_FALSE(synthesis->preview()->isVisible());
  journey.check("Use this linkage");
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK_FALSE(window.document()->mechanism() == chosen);
  journey.check("Ctrl+Z");
}

TEST_CASE("compare the thesis's Excel table with a typo: the proposed map, the typo flagged", "[journey][compare]") {
  test::Journey journey;
  QTemporaryDir dir;
  std::ifstream in(std::string(LINKWRIGHT_TEST_DATA) + "/compare/thesis_excel_table7.tsv");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string right = "90\t16,10\t80,72", wrong = "90\t16,10\t83,72";
  REQUIRE(text.find(right) != std::string::npos);
  text.replace(text.find(right), right.size(), wrong);
  const QString path = dir.filePath("excel.tsv");
  std::ofstream(path.toStdString()) << text;
  journey.answerFileDialog(path);
  journey.menu({"File", "Compare"});
  auto* dialog = journey.window().findChild<ui::CompareDialog*>();
  REQUIRE(dialog != nullptr);
  // The headers proposed the whole map; Compare runs it.
  for (QPushButton* button : dialog->findChildren<QPushButton*>())
    if (button->text().remove('&') == "Compare") QTest::mouseClick(button, Qt::LeftButton);
  journey.settle();
  REQUIRE(dialog->comparison().has_value());
  const kinematics::compare::Comparison& c = *dialog->comparison();
  CHECK(c.offsetDeg == 0.0);
  CHECK(c.columns.size() == 6);
  CHECK(c.columns[1].flagged == 1);  // θ4 at 90°, the typo
  CHECK(c.columns[0].flagged == 0);
  CHECK(c.columns[5].flagged == 8);  // α4, the thesis's own
  CHECK(journey.window().plots()->hasComparison());
  journey.check("File ▸ Compare, Compare");
  dialog->close();
  journey.example("shaper");
  CHECK_FALSE(journey.window().plots()->hasComparison());
  journey.check("Examples ▸ shaper after Compare");
}

TEST_CASE("every example with every view on", "[journey][views]") {
  test::Journey journey;
  for (const QStringList& view :
       {QStringList{"View", "Instant centres and centrodes"}, QStringList{"View", "Velocity arrows"},
        QStringList{"View", "Acceleration arrows"}, QStringList{"View", "Force arrows"}})
    journey.menu(view);
  journey.menu({"View", "Velocity and acceleration polygons"});
  for (const kinematics::Example& e : kinematics::examples()) {
    journey.example(e.name);
    journey.check("every view, Examples ▸ " + e.name);
  }
  journey.menu({"View", "Forces and masses"});
  journey.example("funsho-fourbar");
  journey.check("Forces tab, funsho");
}
