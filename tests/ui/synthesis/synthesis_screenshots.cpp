// Renders the main window with its Synthesis tab open on each problem (the first candidate
// chosen and previewed on the canvas) to PNG files in the directory given as the first
// argument, offscreen, to look at them. Not a test.
#include "ui/main_window.h"
#include "ui/synthesis/candidate_table.h"
#include "ui/synthesis/path_search_worker.h"
#include "ui/synthesis/synthesis_panel.h"

#include <QApplication>
#include <QDir>
#include <QTabWidget>
#include <QTextStream>
#include <QThread>

using namespace linkwright::ui;

namespace {

void settle() {
  for (int i = 0; i < 10; ++i) QApplication::processEvents();
}

void save(QWidget& w, const QString& dir, const QString& name) {
  settle();
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
  window.findChild<QTabWidget*>("AnalysisTabs")->setCurrentIndex(2);
  SynthesisPanel* panel = window.synthesisPanel();
  const QStringList names{"crank_rocker", "slider_crank", "shaper", "function", "motion", "path"};
  for (int i = 0; i < names.size(); ++i) {
    panel->setProblem(static_cast<SynthesisProblem>(i));
    if (i == static_cast<int>(SynthesisProblem::Path)) {
      panel->startPathSearch();
      while (panel->pathSearch()->isRunning()) {
        QApplication::processEvents();
        QThread::msleep(10);
      }
    }
    save(window, dir, QStringLiteral("synthesis_%1.png").arg(names[i]));
  }
  // The crank-rocker's best candidate adopted: the document's own drawing and analysis.
  panel->setProblem(SynthesisProblem::Swing);
  (void)panel->useChosen();
  window.settle();
  save(window, dir, QStringLiteral("synthesis_used.png"));
  return 0;
}
