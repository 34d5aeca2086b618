// Drag-to-redraw latency of the real window, offscreen: a mouse drag of a joint on the canvas
// (C of the default four-bar, or the last point of a built-in example), each move followed by
// everything it triggers (the drag, the document's validation and sweeps, the analysis, the
// canvas items, all plot series) and the repaint that Qt then does of the widgets that
// changed; also the worst case of repainting the whole window. Prints the median and the 95th
// percentile per move. Timing lives here, never in a pass/fail test.
//
//   build/bin/linkwright_gui_benchmark [moves] [example]      (default 400, the thesis four-bar)

#include "ui/canvas/linkage_view.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"
#include "ui/main_window.h"

#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"

#include <QApplication>
#include <QTest>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(std::lround(p * static_cast<double>(values.size() - 1)));
  return values[index];
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  QApplication::setOrganizationName("LinkwrightBenchmark");
  const int moves = argc > 1 ? std::max(10, std::atoi(argv[1])) : 400;

  linkwright::ui::MainWindow window;
  window.resize(1400, 880);
  window.show();
  QApplication::processEvents();
  auto* doc = window.document();
  auto* canvas = window.canvas();
  if (argc > 2) {
    const auto example = linkwright::kinematics::designForExample(argv[2]);
    if (!example) {
      std::fprintf(stderr, "linkwright_gui_benchmark: no example named %s\n", argv[2]);
      return 2;
    }
    doc->reset(*example);
    QApplication::processEvents();
  }
  const std::size_t dragged = doc->fourBar() ? doc->fourBar()->c.index : doc->mechanism().points.size() - 1;
  std::printf("%s, dragging %s: %zu samples; plots and canvas redrawn after every move\n",
              argc > 2 ? argv[2] : "thesis four-bar", doc->mechanism().points[dragged].name.c_str(),
              linkwright::kinematics::designSweepSpec(doc->design()).samples);

  const QPointF start = canvas->mapFromScene(linkwright::ui::toQt(doc->pose().position[dragged]));
  const long sweepsBefore = doc->sweepsRun();
  QTest::mousePress(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  std::vector<double> total, solve, full;
  total.reserve(static_cast<std::size_t>(moves));
  for (int i = 0; i < moves; ++i) {
    // Wander a few pixels around the start, as a hand does, staying assemblable.
    const QPoint to = (start + QPointF(12.0 * std::sin(i * 0.1), 8.0 * std::cos(i * 0.13))).toPoint();
    const auto t0 = std::chrono::steady_clock::now();
    QTest::mouseMove(canvas->viewport(), to);
    const auto t1 = std::chrono::steady_clock::now();
    // Qt's own path to the screen: deferred scene and chart updates, then the update request
    // that paints every dirty widget into the backing store and flushes it.
    QApplication::processEvents();
    QApplication::sendPostedEvents();
    QApplication::processEvents();
    const auto t2 = std::chrono::steady_clock::now();
    window.repaint();  // worst case: every widget of the window painted again
    const auto t3 = std::chrono::steady_clock::now();
    solve.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    total.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
    full.push_back(std::chrono::duration<double, std::milli>(t3 - t2).count() + solve.back());
  }
  QTest::mouseRelease(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  std::printf("moves: %d, undo steps: %d, sweeps: %.2f per move\n", moves, doc->undoStack()->count(),
              static_cast<double>(doc->sweepsRun() - sweepsBefore) / moves);
  std::printf("drag handling (core solve + document + item updates): median %.2f ms, p95 %.2f ms\n",
              percentile(solve, 0.5), percentile(solve, 0.95));
  std::printf("drag to redraw (handling + Qt's repaint of what changed): median %.2f ms, p95 %.2f ms, max %.2f ms\n",
              percentile(total, 0.5), percentile(total, 0.95), *std::max_element(total.begin(), total.end()));
  std::printf("worst case (handling + whole window repainted):        median %.2f ms, p95 %.2f ms\n",
              percentile(full, 0.5), percentile(full, 0.95));
  std::printf("one frame at 60 Hz: 16.67 ms\n");
  return 0;
}
