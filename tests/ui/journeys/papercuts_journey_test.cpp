// The smaller papercuts a new user met, as they met them: Help had only About; Export ▸ Image
// wrote the canvas and every plot as four files without asking which; the arm's elbow branch
// was called Open/Crossed.

#include "tests/ui/journeys/journey.h"

#include "ui/dialogs/getting_started.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/dimensions_panel.h"

#include "kinematics/model/mechanism.h"
#include "tests/support/catch.h"

#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QInputDialog>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>

using namespace linkwright;

TEST_CASE("F1 opens a getting-started page that links to the documentation", "[journey][help]") {
  test::Journey journey;
  journey.key(Qt::Key_F1);
  auto* page = journey.window().findChild<ui::GettingStartedDialog*>();
  REQUIRE(page != nullptr);
  CHECK(page->isVisible());
  const QString text = page->page()->toPlainText();
  for (const char* step : {"Examples", "Drag", "Space", "Ctrl+Z", "Compare", "Presentation mode"})
    CHECK(text.contains(QString::fromUtf8(step)));
  CHECK(page->page()->toHtml().contains(QString::fromLatin1(ui::kDocumentationUrl)));
  page->close();
  journey.check("F1, Close");
  // And from the menu.
  journey.menu({"Help", "Getting started"});
  CHECK(journey.window().findChild<ui::GettingStartedDialog*>()->isVisible());
}

namespace {

// Export ▸ Image, answering "Image of:" with `choice` and the file dialog with `path`.
void exportImage(test::Journey& journey, const QString& choice, const QString& path) {
  journey.whenDialogOpens<QInputDialog>([&journey, choice, path](QInputDialog* ask) {
    REQUIRE(ask->comboBoxItems().contains(choice));
    journey.answerFileDialog(path);
    ask->setTextValue(choice);
    ask->accept();
  });
  journey.menu({"File", "Export", "Image of the canvas or a plot"});
}

}  // namespace

TEST_CASE("Export ▸ Image asks which image and writes that one", "[journey][export]") {
  test::Journey journey;
  QTemporaryDir dir;
  exportImage(journey, "Plot: Angular velocities", dir.filePath("omega.png"));
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList{"omega.png"});
  journey.check("Export ▸ Image, one plot");
  exportImage(journey, "Canvas", dir.filePath("canvas.svg"));
  CHECK(QDir(dir.path()).entryList(QDir::Files) == QStringList({"canvas.svg", "omega.png"}));
  exportImage(journey, "Canvas and every plot shown", dir.filePath("all.png"));
  CHECK(QDir(dir.path()).entryList({"all*"}, QDir::Files) ==
        QStringList({"all-plot1.png", "all-plot2.png", "all-plot3.png", "all.png"}));
  journey.check("Export ▸ Image, all");
}

TEST_CASE("the arm's elbow branch reads elbow up or down, as its pose shows", "[journey][arm]") {
  test::Journey journey;
  journey.example("seed-arm");
  const kinematics::Mechanism& arm = journey.window().document()->mechanism();
  std::optional<kinematics::PointId> elbow;
  for (std::size_t i = 0; i < arm.points.size(); ++i)
    if (arm.points[i].name == "elbow") elbow = kinematics::PointId{i};
  REQUIRE(elbow);
  QComboBox* branch = journey.window().dimensionsPanel()->branchBox(*elbow);
  REQUIRE(branch != nullptr);
  CHECK(branch->itemText(0) == "Elbow up");
  CHECK(branch->itemText(1) == "Elbow down");
  // Seed 004's arm works elbow down: the elbow right of the line from the shoulder to the tip.
  const auto side = [&journey] {
    const kinematics::Mechanism& m = journey.window().document()->mechanism();
    const kinematics::Pose& pose = journey.window().document()->pose();
    std::size_t shoulder = 0, tip = 0, joint = 0;
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      if (m.points[i].name == "O") shoulder = i;
      if (m.points[i].name == "tip") tip = i;
      if (m.points[i].name == "elbow") joint = i;
    }
    const Eigen::Vector2d a = pose.position[tip] - pose.position[shoulder];
    const Eigen::Vector2d b = pose.position[joint] - pose.position[shoulder];
    return a.x() * b.y() - a.y() * b.x();  // > 0: left of shoulder → tip
  };
  CHECK(branch->currentText() == "Elbow down");
  CHECK(side() < 0.0);
  journey.check("Examples ▸ seed-arm");
  branch->setFocus();
  journey.key(Qt::Key_Up);
  CHECK(branch->currentText() == "Elbow up");
  CHECK(side() > 0.0);
  journey.check("branch: Elbow up");
}
