// linkwright: the designer window (see --help). Wiring only: the window and the core do the work.
#include "app/gui_options.h"

#include "ui/animation/crank_animator.h"
#include "ui/classroom/inversion_cells.h"
#include "ui/classroom/inversions_window.h"
#include "ui/compare/column_map_editor.h"
#include "ui/compare/compare_dialog.h"
#include "ui/document/mechanism_document.h"
#include "ui/export/cycle_animation.h"
#include "ui/main_window.h"
#include "ui/message_banner.h"
#include "ui/plots/plot_panel.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <QApplication>
#include <QGraphicsView>
#include <QIcon>
#include <QLabel>
#include <QTimer>

#include <iostream>

namespace {

// Shows the window and lets it settle as the event loop would before the first frame.
void showSettled(linkwright::ui::MainWindow& window) {
  window.show();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  // The plots' width and the quality estimate wait for the window to settle; not here.
  window.settle();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  // Outside exec() nothing deletes what deleteLater() was asked to: Qt Charts' items of series
  // taken off a chart (a new linkage's curves) would still be drawn where they last were.
  QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
}

// Shows the window, lets layout and first paint settle, saves it as a PNG and quits.
int takeScreenshot(linkwright::ui::MainWindow& window, const QString& path) {
  showSettled(window);
  if (!window.grab().save(path, "PNG")) {
    std::cerr << "linkwright: cannot write the screenshot " << path.toStdString() << "\n";
    return 1;
  }
  return 0;
}

// View ▸ Inversions… of the linkage, its cranks a step (30°) on from where they start, so that
// no crank lies along the frame line.
int takeInversionsScreenshot(linkwright::ui::MainWindow& window, const QString& path) {
  if (const auto why = linkwright::ui::inversionsUnavailable(window.document()->design())) {
    std::cerr << "linkwright: --inversions-screenshot: " << why->toStdString() << "\n";
    return 2;
  }
  linkwright::ui::InversionsWindow* inversions = window.showInversions();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  inversions->step();
  for (int i = 0; i < 5; ++i) QApplication::processEvents();
  if (!inversions->grab().save(path, "PNG")) {
    std::cerr << "linkwright: cannot write the screenshot " << path.toStdString() << "\n";
    return 1;
  }
  return 0;
}

// Like the screenshot: the window settles, then the canvas is rendered over one cycle.
int writeAnimation(linkwright::ui::MainWindow& window, const linkwright::app::GuiOptions& options) {
  showSettled(window);
  linkwright::ui::AnimationSettings settings;
  settings.frames = options.frames;
  settings.frameDelayMs = options.frameDelayMs;
  settings.frameRate = options.frameRate;
  if (options.animationSize) settings.size = QSize(options.animationSize->first, options.animationSize->second);
  if (!window.exportAnimation(QString::fromStdString(*options.animation), settings)) {
    std::cerr << "linkwright: " << window.banner()->text().toStdString() << "\n";
    return 1;
  }
  return 0;
}

// File ▸ Export ▸ Image of the canvas or of one plot, once the window has settled.
int writeImage(linkwright::ui::MainWindow& window, const linkwright::app::GuiOptions& options) {
  showSettled(window);
  const QString path = QString::fromStdString(*options.image);
  bool written = false;
  if (options.imagePlot) {
    // Counted as Export ▸ Image's "Canvas and every plot shown" names its files (-plot1, …).
    const QList<QGraphicsView*> views = window.plots()->graphicsViews();
    const int index = *options.imagePlot - 1;
    if (index >= views.size() || views[index]->isHidden()) {
      QStringList shown;
      for (int i = 0; i < views.size(); ++i)
        if (!views[i]->isHidden()) shown << QStringLiteral("plot%1").arg(i + 1);
      std::cerr << "linkwright: --image-of: plot" << *options.imagePlot << " is not shown (shown: "
                << (shown.isEmpty() ? QStringLiteral("none") : shown.join(QStringLiteral(", "))).toStdString() << ")\n";
      return 2;
    }
    written = window.exportPlotImage(index, path);
  } else {
    written = window.exportCanvasImage(path);
  }
  if (!written) {
    std::cerr << "linkwright: " << window.banner()->text().toStdString() << "\n";
    return 1;
  }
  return 0;
}

// --compare: File ▸ Compare… on the table, mapped and compared at once with --compare-map (and
// so drawn on the plots).
// Returns the dialog, or nullptr (the reason on stderr) when the table or the map is refused.
linkwright::ui::CompareDialog* openComparison(linkwright::ui::MainWindow& window,
                                              const linkwright::app::GuiOptions& o) {
  namespace kc = linkwright::kinematics::compare;
  auto* dialog = window.openCompareTable(QString::fromStdString(*o.compare));
  if (dialog == nullptr) {
    std::cerr << "linkwright: " << window.banner()->text().toStdString() << "\n";
    return nullptr;
  }
  if (!o.compareMap) return dialog;
  const auto mapping = kc::parseColumnMap(*o.compareMap, window.document()->mechanism());
  if (!mapping) {
    std::cerr << "linkwright: " << mapping.error().message << "\n";
    return nullptr;
  }
  dialog->mapEditor()->setMapping(*mapping);
  if (!dialog->compare()) std::cerr << "linkwright: " << dialog->messageLabel()->text().toStdString() << "\n";
  return dialog;
}

// Ticks exactly the quantities named in `keys`, or says which key the linkage lacks.
bool selectPlots(linkwright::ui::MainWindow& window, const std::string& keys) {
  linkwright::ui::PlotPanel* plots = window.plots();
  QString unknown;
  const auto selection =
      linkwright::ui::selectionOfKeys(plots->curves(), QString::fromStdString(keys).split(QLatin1Char(',')), unknown);
  if (!selection) {
    QStringList known;
    for (const auto& curve : plots->curves()) known << curve.key;
    std::cerr << "linkwright: --plots: this linkage has no quantity '" << unknown.toStdString()
              << "' (it has: " << known.join(QStringLiteral(", ")).toStdString() << ")\n";
    return false;
  }
  plots->setSelection(*selection);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  std::string error;
  const auto options = linkwright::app::parseGuiOptions(args, error);
  if (!options) {
    std::cerr << "linkwright: " << error << "\n";
    return 2;
  }
  if (options->help) {
    std::cout << linkwright::app::guiUsage();
    return 0;
  }
  if (options->version) {
    std::cout << "linkwright " << LINKWRIGHT_VERSION << "\n";
    return 0;
  }
  QApplication app(argc, argv);
  QApplication::setApplicationName("Linkwright");
  QApplication::setOrganizationName("Linkwright");
  QApplication::setApplicationVersion(LINKWRIGHT_VERSION);
  QApplication::setWindowIcon(QIcon(":/icons/linkwright.svg"));

  linkwright::ui::MainWindow window;
  // A drag's slow sweeps (a Newton linkage at Precise) go to a worker; the tests' windows keep
  // the default, in which every edit's sweep is there at once.
  window.document()->setSweepThreading(linkwright::ui::DisplaySweeper::Threading::Adaptive);
  namespace k = linkwright::kinematics;
  if (options->example)
    window.newDocument(*k::designForExample(*options->example), QString::fromStdString(*options->example));
  if (options->file && !window.openFile(QString::fromStdString(*options->file))) {
    std::cerr << "linkwright: " << window.banner()->text().toStdString() << "\n";
    if (options->screenshot || options->animation || options->inversionsScreenshot || options->image) return 2;
  }
  if (options->windowSize) window.resize(options->windowSize->first, options->windowSize->second);
  if (options->crankAngleDeg) window.document()->setCrankAngle(k::degToRad(*options->crankAngleDeg));
  if (options->presentation) window.setPresentationMode(true);
  if (options->highContrast) window.setHighContrast(true);
  if (options->forces) window.showForces();
  if (options->centres) window.setShowInstantCentres(true);
  if (options->plots && !selectPlots(window, *options->plots)) return 2;
  if (options->animation) return writeAnimation(window, *options);
  if (options->inversionsScreenshot)
    return takeInversionsScreenshot(window, QString::fromStdString(*options->inversionsScreenshot));
  // With --screenshot or --image, the designer is rendered with the table's rows on its plots.
  if (options->compare && openComparison(window, *options) == nullptr && (options->screenshot || options->image))
    return 2;
  if (options->image) return writeImage(window, *options);
  if (options->screenshot) return takeScreenshot(window, QString::fromStdString(*options->screenshot));
  window.show();
  QTimer::singleShot(0, window.animator(), &linkwright::ui::CrankAnimator::play);
  return QApplication::exec();
}
