// Renders the main window with its Polygons tab open (and the tab alone, larger) on the
// thesis crank-rocker and on the shaper, whose slotted link brings the Coriolis term, to PNG
// files in the directory given as the first argument, offscreen, to look at them. Not a test.
#include "ui/classroom/polygon_panel.h"
#include "ui/document/mechanism_document.h"
#include "ui/main_window.h"

#include "kinematics/analysis/vector_polygon.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"

#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTextStream>

using namespace linkwright;
using namespace linkwright::ui;

namespace {

void save(QWidget& w, const QString& dir, const QString& name) {
  for (int i = 0; i < 10; ++i) QApplication::processEvents();
  const QString path = QDir(dir).filePath(name);
  w.grab().save(path);
  QTextStream(stdout) << path << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("LinkwrightScreenshots");
  const QString dir = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QStringLiteral("/tmp");
  MainWindow window;
  window.resize(1500, 900);
  window.show();
  window.settle();
  window.findChild<QTabWidget*>("AnalysisTabs")->setCurrentIndex(3);
  PolygonPanel* panel = window.polygonPanel();
  const struct {
    const char* example;
    double deg;
  } shots[] = {{"thesis-crank-rocker", 30.0}, {"shaper", 60.0}};
  for (const auto& shot : shots) {
    window.newDocument(*kinematics::designForExample(shot.example));
    window.document()->setCrankAngle(kinematics::degToRad(shot.deg));
    const QString base = QString::fromLatin1(shot.example);
    panel->setKind(kinematics::PolygonKind::Velocity);
    save(window, dir, QStringLiteral("polygon_window_%1.png").arg(base));
    PolygonPanel alone(window.document());
    alone.resize(760, 900);
    alone.show();
    for (const auto kind : {kinematics::PolygonKind::Velocity, kinematics::PolygonKind::Acceleration}) {
      alone.setKind(kind);
      const bool v = kind == kinematics::PolygonKind::Velocity;
      save(alone, dir, QStringLiteral("polygon_%1_%2.png").arg(base, v ? "velocity" : "acceleration"));
    }
    alone.reset();
    for (int i = 0; i < 3; ++i) alone.step();
    save(alone, dir, QStringLiteral("polygon_%1_step3.png").arg(base));
  }
  // The lecture hall: presentation mode, the shaper's acceleration polygon.
  window.setPresentationMode(true);
  panel->setKind(kinematics::PolygonKind::Acceleration);
  save(window, dir, QStringLiteral("polygon_window_presentation.png"));
  return 0;
}
