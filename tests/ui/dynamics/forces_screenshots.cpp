// Renders the forces widgets (dynamics panel, force plots, canvas arrows) on built-in examples
// to PNG files in the directory given as the first argument, offscreen, to look at them.
#include "ui/canvas/force_arrows_item.h"
#include "ui/canvas/linkage_view.h"
#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/panels/dynamics_panel.h"
#include "ui/plots/force_plot_panel.h"
#include "ui/plots/machine_page.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <QApplication>
#include <QDir>
#include <QGraphicsScene>
#include <QTabWidget>
#include <QTextStream>

namespace k = linkwright::kinematics;
using namespace linkwright::ui;

namespace {

void settle() {
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
}

void save(QWidget& w, const QString& dir, const QString& name, QSize size) {
  w.resize(size);
  w.show();
  settle();
  const QString path = QDir(dir).filePath(name);
  w.grab().save(path);
  QTextStream(stdout) << path << "\n";
}

// Gives a linkage without masses some: 0.5 kg per link, 0.4 kg per slider block.
void addMasses(k::Design& design) {
  if (!design.dynamics.empty()) return;
  for (const k::Link& link : design.mechanism.links)
    design.dynamics.links.push_back({link.name, 0.5, std::nullopt, std::nullopt});
  for (const k::Point& p : design.mechanism.points)
    if (std::holds_alternative<k::RrpPoint>(p.definition)) design.dynamics.sliders.push_back({p.name, 0, 0.4, 0.0});
}

void shoot(const std::string& example, double crankDeg, const QString& dir, bool masses) {
  MechanismDocument doc;
  k::Design design = *k::designForExample(example);
  if (masses) addMasses(design);
  else design.dynamics = {};
  doc.reset(design);
  doc.setRequest(ForceResults::forcesRequest(doc.request()));
  doc.setCrankAngle(k::degToRad(crankDeg));
  ForceResults forces(&doc);
  forces.setEnabled(true);
  const QString tag = QString::fromStdString(example) + (masses ? "" : "_nomass") + QStringLiteral("_%1").arg(crankDeg);

  DynamicsPanel panel(&doc);
  save(panel, dir, tag + "_panel.png", {460, 600});
  ForcePlotPanel plots(&doc, &forces);
  save(plots, dir, tag + "_plots.png", {1000, 560});
  if (auto* tabs = plots.findChild<QTabWidget*>()) {
    tabs->setCurrentIndex(2);  // the polar load diagrams
    save(plots, dir, tag + "_polar.png", {1000, 560});
    tabs->setCurrentIndex(3);  // the flywheel and motor, computed on the worker pool
    plots.resize(1000, 560);
    settle();
    plots.machinePage()->waitForFigures();
    save(plots, dir, tag + "_flywheel.png", {1000, 560});
  }

  LinkageView view(&doc);
  auto* arrows = new ForceArrowsItem;
  view.linkageScene()->addItem(arrows);
  arrows->setForces(doc, forces);
  QObject::connect(&forces, &ForceResults::changed, &view, [&] { arrows->setForces(doc, forces); });
  save(view, dir, tag + "_canvas.png", {700, 480});
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  const QString dir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QDir::currentPath();
  QDir().mkpath(dir);
  shoot("funsho-fourbar", 60.0, dir, true);
  shoot("funsho-fourbar", 10.0, dir, true);
  shoot("funsho-fourbar", 60.0, dir, false);
  shoot("ls3-engine", 60.0, dir, true);
  return 0;
}
