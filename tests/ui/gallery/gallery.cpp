// Not a test: the designer's gallery. Renders every built-in example in every view a user can
// turn on (the drawing, instant centres, forces with their arrows, the polygons, every plot
// including the ratios) to DIR/<example>-<view>.png, and with --docs also writes the README's
// and docs' designer images (docs/images) under their names, so that they are retaken from one
// command:
//   QT_QPA_PLATFORM=offscreen BUILD/bin/linkwright_gallery DIR [--docs docs/images]
// Look at every picture it writes before a change to a view is called done. docs/classroom.md
// and docs/compare.md give the commands for the presentation, inversion, polygon and compare
// images, which need their own screen size or tool.

#include "ui/classroom/atlas_window.h"
#include "ui/classroom/cognates_window.h"
#include "ui/compare/compare_dialog.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"
#include "ui/plots/force_plot_panel.h"
#include "ui/plots/optimise_window.h"
#include "ui/plots/plot_panel.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/tolerance_window.h"

#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/mass_properties.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>

#include <array>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace k = linkwright::kinematics;
using linkwright::ui::MainWindow;

namespace {

void settle(MainWindow& window) {
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  window.settle();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

// The View menu's action named `text` ('&' ignored), as a person chooses it.
QAction* viewAction(MainWindow& window, const QString& text) {
  for (QAction* menu : window.menuBar()->actions())
    if (menu->text().remove('&') == "View")
      for (QAction* action : menu->menu()->actions())
        if (action->text().remove('&') == text) return action;
  return nullptr;
}

void showEveryPlot(MainWindow& window) {
  QStringList keys;
  for (const auto& curve : window.plots()->curves()) keys << curve.key;
  QString unknown;
  if (const auto selection = linkwright::ui::selectionOfKeys(window.plots()->curves(), keys, unknown))
    window.plots()->setSelection(*selection);
}

// The ratio plots (velocity ratio, mechanical advantage) beside the angles.
void showRatios(MainWindow& window) {
  QStringList keys;
  for (const auto& curve : window.plots()->curves())
    if (curve.key.contains("ratio") || curve.key.contains("advantage") || curve.key.endsWith("_angle"))
      keys << curve.key;
  QString unknown;
  if (const auto selection = linkwright::ui::selectionOfKeys(window.plots()->curves(), keys, unknown))
    window.plots()->setSelection(*selection);
}

struct View {
  const char* name;
  std::function<void(MainWindow&)> show;
};

const std::vector<View>& views() {
  static const std::vector<View> all{
      {"designer", [](MainWindow&) {}},
      {"centres", [](MainWindow& w) { viewAction(w, "Instant centres and centrodes")->setChecked(true); }},
      {"forces", [](MainWindow& w) { w.showForces(); }},
      {"shaking",
       [](MainWindow& w) {
         w.showForces();
         w.forcePlots()->pages()->setCurrentIndex(1);
       }},
      {"shaking-polar",
       [](MainWindow& w) {
         w.showForces();
         w.forcePlots()->pages()->setCurrentIndex(2);
         QComboBox* of = w.forcePlots()->jointSelector();
         of->setCurrentIndex(of->count() - 1);
       }},
      {"balanced",
       [](MainWindow& w) {
         w.showForces();
         w.balanceAction()->trigger();
         w.forcePlots()->pages()->setCurrentIndex(1);
       }},
      {"balanced-forces",
       [](MainWindow& w) {
         w.showForces();
         w.balanceAction()->trigger();
       }},
      {"boom-spring",
       [](MainWindow& w) {
         // A 200 kg boom under gravity with a spring from its eye C to a frame point S above O
         // that carries part of its weight: the spring drawn as coils, its force in the cylinder's.
         k::Design d = w.document()->design();
         if (!d.mechanism.findLink("boom")) return;  // the view is the boom's alone
         d.mechanism.points.push_back({"S", k::GroundPoint{Eigen::Vector2d(0.0, 1.2)}});
         d.dynamics.links = {{"boom", 200.0, std::nullopt, std::nullopt}};
         d.dynamics.loads.gravity = k::standardGravity();
         d.dynamics.loads.springs = {{"lift", {"boom", "C"}, {"", "S"}, 20000.0, 0.4, 0.0}};
         if (w.document()->edit(d, "spring")) std::cerr << "linkwright_gallery: the boom's spring was refused\n";
         w.showForces();
       }},
      {"cognates",
       [](MainWindow& w) {
         // The Miranda four-bar with its coupler point lifted off the coupler line.
         if (w.windowTitle().contains("miranda")) {
           auto lifted =
               k::fourBarDesign({250.0, 100.0, 225.0, 150.0}, k::Branch::Open, "mm", k::CouplerPointSpec{112.5, 80.0});
           if (lifted) w.document()->edit(*lifted, "coupler point");
         }
         w.document()->setCrankAngle(k::degToRad(60.0));
         w.showCognates();
       }},
      {"tolerances", [](MainWindow& w) { w.showTolerances(); }},
      {"optimise",
       [](MainWindow& w) {
         // Edit ▸ Optimise…: the rocker's peak α, run to its end, before and after shown.
         auto* optimise = w.showOptimise();
         optimise->linkBox()->setCurrentText("rocker");
         optimise->evaluationsField()->setValue(400);
         QEventLoop loop;
         QObject::connect(optimise, &linkwright::ui::OptimiseWindow::runEnded, &loop, &QEventLoop::quit);
         optimise->runButton()->click();
         loop.exec();
       }},
      {"optimise-path",
       [](MainWindow& w) {
         // Edit ▸ Optimise… on a coupler point's path: targets on the curve of P lifted 30 mm
         // off the coupler, typed as a person would; the path before and after, the targets.
         const auto lifted =
             k::fourBarDesign({250.0, 100.0, 225.0, 150.0}, k::Branch::Open, "mm", k::CouplerPointSpec{112.5, 30.0});
         if (!lifted || !w.document()->design().mechanism.findPoint("P")) return;
         QStringList targets;
         for (const double deg : {0.0, 72.0, 144.0, 216.0, 288.0}) {
           const Eigen::Vector2d p = k::solvePose(lifted->mechanism, {k::degToRad(deg), 0.0, 0.0})
                                         .value()
                                         .position[lifted->mechanism.findPoint("P")->index];
           targets << QString::number(p.x(), 'f', 2) + ", " + QString::number(p.y(), 'f', 2);
         }
         auto* optimise = w.showOptimise();
         optimise->objectiveBox()->setCurrentIndex(2);
         optimise->pointBox()->setCurrentText("P");
         optimise->targetsField()->setText(targets.join("; "));
         optimise->evaluationsField()->setValue(600);
         QEventLoop loop;
         QObject::connect(optimise, &linkwright::ui::OptimiseWindow::runEnded, &loop, &QEventLoop::quit);
         optimise->runButton()->click();
         loop.exec();
       }},
      {"flywheel",
       [](MainWindow& w) {
         w.showForces();
         w.forcePlots()->pages()->setCurrentIndex(3);
       }},
      {"polygons", [](MainWindow& w) { viewAction(w, "Velocity and acceleration polygons")->trigger(); }},
      {"plots", showEveryPlot},
      {"ratios", showRatios},
      {"centres-ratios",
       [](MainWindow& w) {
         viewAction(w, "Instant centres and centrodes")->setChecked(true);
         showRatios(w);
       }},
  };
  return all;
}

bool render(const std::string& example, const View& view, double crankDeg, const QString& path) {
  MainWindow window;
  window.resize(1400, 880);
  window.newDocument(*k::designForExample(example), QString::fromStdString(example));
  window.show();
  settle(window);
  view.show(window);
  if (crankDeg != 0.0) window.document()->setCrankAngle(k::degToRad(crankDeg));
  settle(window);
  // A view that opens a window of its own (View ▸ Cognates…) is pictured by that window.
  QWidget* shown = &window;
  if (auto* cognates = window.findChild<linkwright::ui::CognatesWindow*>(); cognates && cognates->isVisible())
    shown = cognates;
  if (auto* tolerances = window.findChild<linkwright::ui::ToleranceWindow*>(); tolerances && tolerances->isVisible()) {
    tolerances->waitForStudy();  // it runs on the worker pool
    settle(window);
    shown = tolerances;
  }
  if (auto* optimise = window.findChild<linkwright::ui::OptimiseWindow*>(); optimise && optimise->isVisible())
    shown = optimise;
  if (!shown->grab().save(path, "PNG")) {
    std::cerr << "linkwright_gallery: cannot write " << path.toStdString() << "\n";
    return false;
  }
  return true;
}

const View& viewNamed(const std::string& name) {
  for (const View& v : views())
    if (name == v.name) return v;
  return views().front();
}

// The designer images the README and docs show, by name: example, view, crank angle.
struct DocImage {
  const char* file;
  const char* example;
  const char* view;
  double crankDeg;
};
constexpr DocImage kDocImages[] = {
    {"designer.png", "thesis-crank-rocker", "designer", 30.0},
    {"shaper.png", "shaper", "designer", 60.0},
    {"ls3-engine.png", "ls3-engine", "designer", 40.0},
    {"watt-ii.png", "watt-ii", "designer", 30.0},
    {"forces.png", "funsho-fourbar", "forces", 60.0},
    {"shaking.png", "funsho-fourbar", "shaking", 60.0},
    {"flywheel.png", "funsho-fourbar", "flywheel", 60.0},
    {"cognates.png", "miranda-fourbar", "cognates", 0.0},
    {"tolerances.png", "thesis-crank-rocker", "tolerances", 0.0},
    {"optimise.png", "thesis-crank-rocker", "optimise", 0.0},
    {"optimise_path.png", "miranda-fourbar", "optimise-path", 0.0},
    {"boom_spring.png", "excavator-boom", "boom-spring", 0.0},
    {"balanced.png", "funsho-fourbar", "balanced", 60.0},
    {"balanced_forces.png", "funsho-fourbar", "balanced-forces", 60.0},
    {"instant_centres.png", "thesis-crank-rocker", "centres", 250.0},
    {"instant_centres_shaper.png", "shaper", "centres-ratios", 30.0},
    {"ratios.png", "thesis-crank-rocker", "ratios", 30.0},
};

}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  const QStringList args = QApplication::arguments().mid(1);
  if (args.isEmpty() || args.front().startsWith('-')) {
    std::cerr << "usage: linkwright_gallery DIR [--docs DOCS_IMAGES_DIR]\n";
    return 2;
  }
  const QDir out(args.front());
  if (!out.mkpath(".")) return 1;
  int written = 0;
  for (const k::Example& example : k::examples())
    for (const View& view : views()) {
      // For the docs only: the ratios beside the centres, and an optimisation (a run per example).
      if (std::string(view.name) == "centres-ratios" || std::string(view.name).rfind("optimise", 0) == 0) continue;
      const QString path = out.filePath(QString::fromStdString(example.name) + "-" + view.name + ".png");
      if (!render(example.name, view, 30.0, path)) return 1;
      ++written;
    }
  const qsizetype docs = args.indexOf("--docs");
  if (docs > 0 && docs + 1 < args.size()) {
    const QDir images(args[docs + 1]);
    for (const DocImage& image : kDocImages) {
      if (!render(image.example, viewNamed(image.view), image.crankDeg, images.filePath(image.file))) return 1;
      ++written;
    }
  }
  // View ▸ Atlas… on a grid that holds Hoeken's straight-line linkage (coupler 2.5, rocker 2.5,
  // frame 2, P 2 along), once every cell is computed: the window docs/atlas.md shows.
  if (docs > 0 && docs + 1 < args.size()) {
    MainWindow window;
    window.resize(1400, 880);
    window.show();
    settle(window);
    linkwright::ui::AtlasWindow* atlas = window.showAtlas();
    const std::array<QString, 5> grid{"2,2.5,3", "2.5", "2,3", "0.5,1,2", "0,0.5"};
    for (int i = 0; i < 5; ++i) atlas->axisField(i)->setText(grid[static_cast<std::size_t>(i)]);
    atlas->showGrid();
    QElapsedTimer waited;
    waited.start();
    while (!atlas->complete() && waited.elapsed() < 60000) QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (!atlas->complete()) return 1;
    settle(window);
    if (!atlas->grab().save(QDir(args[docs + 1]).filePath("atlas.png"), "PNG")) return 1;
    ++written;
  }
  // File ▸ Compare… on the thesis's Excel table (run from the source tree), its map proposed
  // by the headers: the dialog docs/compare.md shows.
  const QString table = "tests/data/compare/thesis_excel_table7.tsv";
  if (docs > 0 && docs + 1 < args.size() && QFile::exists(table)) {
    MainWindow window;
    window.resize(1400, 880);
    window.show();
    settle(window);
    linkwright::ui::CompareDialog* dialog = window.openCompareTable(table);
    if (dialog == nullptr || !dialog->compare()) return 1;
    dialog->resize(1100, 720);
    settle(window);
    if (!dialog->grab().save(QDir(args[docs + 1]).filePath("compare.png"), "PNG")) return 1;
    ++written;
  }
  std::cout << "wrote " << written << " images\n";
  return 0;
}
