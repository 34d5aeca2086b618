// The window with linkages other than four-bars: Export ▸ CSV equals `linkwright-cli analyze
// --example NAME` byte for byte, File ▸ New and the Examples menu offer every kind and example,
// save → open in a new window reproduces the linkage, attaching a dyad turns the dimensions
// panel from the four-bar's named lengths to its points, and a corrupt file changes nothing.

#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"
#include "ui/panels/dimensions_panel.h"

#include "app/cli/cli.h"
#include "kinematics/design/design.h"
#include "kinematics/design/dyad_request.h"

#include "tests/ui/support/read_file.h"

#include "tests/support/catch.h"

#include <QAction>
#include <QCheckBox>
#include <QFile>
#include <QGroupBox>
#include <QMenu>
#include <QMenuBar>
#include <QTemporaryDir>

#include <sstream>

using namespace linkwright;
using test::readAll;
namespace k = linkwright::kinematics;

namespace {

QMenu* topMenu(ui::MainWindow& window, const QString& title) {
  for (QAction* a : window.menuBar()->actions())
    if (a->menu() != nullptr && a->text().remove('&') == title) return a->menu();
  return nullptr;
}

}  // namespace

TEST_CASE("Export ▸ CSV of any example equals linkwright-cli analyze --example", "[ui][window][csv][linkage]") {
  ui::MainWindow window;
  QTemporaryDir dir;
  for (const std::string name : {"ls3-engine", "shaper", "whitworth", "watt-ii", "stephenson-iii"}) {
    CAPTURE(name);
    window.newDocument(*k::designForExample(name));
    const QString path = dir.filePath(QString::fromStdString(name) + ".csv");
    REQUIRE(window.exportCsv(path));
    // The document samples every 0.5° (designFromExample); the CLI is asked for the same grid.
    const k::Design& design = window.document()->design();
    std::ostringstream out, err;
    REQUIRE(cli::runCli({"analyze", "--example", name, "--samples", std::to_string(design.samples)}, out, err) == 0);
    CHECK(readAll(path).toStdString() == out.str());
  }
}

TEST_CASE("File ▸ New offers each kind of linkage and the Examples menu every example", "[ui][window][linkage]") {
  ui::MainWindow window;
  QMenu* file = topMenu(window, "File");
  REQUIRE(file != nullptr);
  QMenu* newMenu = nullptr;
  for (QAction* a : file->actions())
    if (a->menu() != nullptr && a->text().remove('&') == "New") newMenu = a->menu();
  REQUIRE(newMenu != nullptr);
  QStringList kinds;
  for (QAction* a : newMenu->actions()) kinds << a->text().remove('&');
  CHECK(kinds.size() == 11);
  for (QAction* a : newMenu->actions()) {
    CAPTURE(a->text().toStdString());
    a->trigger();
    CHECK(window.document()->undoStack()->count() == 0);
    CHECK(window.document()->poseStatus() != k::PoseStatus::NotAssemblable);
    const bool fourBar = window.document()->fourBar().has_value();
    // One editor: a four-bar's is headed by its named lengths and offers its coupler point.
    CHECK((window.dimensionsPanel()->editor(k::ParameterSlot::CouplerLength) != nullptr) == fourBar);
    CHECK(window.dimensionsPanel()->couplerPointBox()->isVisibleTo(&window) == fourBar);
  }
  QMenu* examples = topMenu(window, "Examples");
  REQUIRE(examples != nullptr);
  std::vector<std::string> names;
  for (const auto& e : k::examples()) names.push_back(e.name);
  for (const std::string& name : names) {
    CAPTURE(name);
    auto* action = examples->findChild<QAction*>(QString::fromStdString("example_" + name));
    if (action == nullptr) action = window.findChild<QAction*>(QString::fromStdString("example_" + name));
    REQUIRE(action != nullptr);
    CHECK_FALSE(action->text().isEmpty());
    action->trigger();
    CHECK(window.document()->design() == *k::designForExample(name));
  }
}

TEST_CASE("a linkage saved in one window opens the same in another", "[ui][window][file][linkage]") {
  QTemporaryDir dir;
  const QString path = dir.filePath("engine.json");
  k::Design saved;
  {
    ui::MainWindow window;
    window.newDocument(*k::designForExample("ls3-engine"));
    k::Design d = window.document()->design();
    std::get<k::RrpPoint>(d.mechanism.points[2].definition).length = 150.0;
    REQUIRE_FALSE(window.document()->edit(d, "rod").has_value());
    REQUIRE(window.saveTo(path));
    saved = window.document()->design();
  }
  ui::MainWindow other;
  REQUIRE(other.openFile(path));
  CHECK(other.document()->design() == saved);
  CHECK(other.dimensionsPanel()->editor(k::ParameterSlot::CouplerLength) == nullptr);
  CHECK(other.dimensionsPanel()->editor(k::ParameterSlot::Length) != nullptr);
}

TEST_CASE("a corrupt or newer file leaves an open linkage as it was", "[ui][window][file][errors][linkage]") {
  QTemporaryDir dir;
  const QString newer = dir.filePath("newer.json");
  {
    QFile f(newer);
    REQUIRE(f.open(QIODevice::WriteOnly));
    f.write("{\"format\": \"linkwright\", \"version\": 99}");
  }
  ui::MainWindow window;
  window.newDocument(*k::designForExample("watt-ii"));
  const k::Design before = window.document()->design();
  CHECK_FALSE(window.openFile(newer));
  CHECK(window.banner()->text().contains("newer Linkwright"));
  CHECK(window.document()->design() == before);
}

TEST_CASE("attaching a dyad in the window swaps the four-bar lengths for the point dimensions",
          "[ui][window][attach]") {
  ui::MainWindow window;
  REQUIRE(window.document()->fourBar().has_value());
  const auto request =
      k::suggestDyad(window.document()->mechanism(), window.document()->crankAngle(), k::DyadKind::Rrr);
  REQUIRE_FALSE(window.attachDyad(request).has_value());
  CHECK_FALSE(window.document()->fourBar().has_value());
  CHECK(window.document()->mechanism().links.size() == 5);
  CHECK(window.dimensionsPanel()->editor(k::ParameterSlot::CouplerLength) == nullptr);
  CHECK_FALSE(window.dimensionsPanel()->couplerPointBox()->isVisibleTo(&window));
  window.document()->undoStack()->undo();
  CHECK(window.document()->fourBar().has_value());
  CHECK(window.dimensionsPanel()->editor(k::ParameterSlot::CouplerLength) != nullptr);
  CHECK(window.dimensionsPanel()->couplerPointBox()->isVisibleTo(&window));
  // A refusal names the reason and changes nothing.
  k::DyadRequest taken = request;
  taken.joint = "C";
  const auto why = window.attachDyad(taken);
  REQUIRE(why.has_value());
  CHECK(why->contains("already a point named C"));
  CHECK(window.document()->fourBar().has_value());
}
