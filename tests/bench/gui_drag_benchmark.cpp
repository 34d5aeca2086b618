// Drag-to-redraw latency of the real window, offscreen: a mouse drag of a joint on the canvas
// (C of a four-bar, or the last point of any other example), each move followed by everything
// it triggers (the drag, the document's validation and sweeps, the analysis, the canvas items,
// all plot series, the forces when they are shown) and the repaint that Qt then does of the
// widgets that changed; also the worst case of repainting the whole window. Prints the median,
// the 95th percentile and the maximum per move, and one RESULT line for tables. Timing lives
// here, never in a pass/fail test.
//
// Wall time counts what a user waits for, including time the GUI thread spent waiting for a
// core that other programs had; the GUI thread's own CPU time per move (CLOCK_THREAD_CPUTIME_ID)
// is what the program itself costs, and is printed too, with the slowest moves, so that a
// loaded machine can still be measured and a slow frame traced to the move that caused it.
//
// The longest event: a move, a worker's result landing and the repaint are separate events of
// the GUI thread's loop, and a display's frame clock paints between them. The longest single
// event handled (QApplication::notify at the top level) is how long the GUI thread cannot
// answer the user: issue 20's "never blocks for more than 16 ms". The window's sweeps are
// threaded as the designer's are (Adaptive: a slow drag's sweep and every drag's design grid
// go to a worker), and a move is redrawn once what it started in a worker (the sweep, the
// grid, the force cycle) has landed and been painted: drag-to-redraw counts the worker's
// time, the GUI thread's figures do not.
//
//   build/bin/linkwright_gui_benchmark [--moves N] [--example NAME] [--quality draft|normal|precise] [--forces] [--trace]
//                                      [--census] [--wander F] [--threading adaptive|gui]
//
// Defaults: 400 moves, the thesis four-bar, Normal, kinematics only. The drag starts once the
// window has settled: the plots have reported their width (which sets the samples shown), the
// first quality estimate has landed and the value axes have settled. --forces shows the Forces
// tab and the force arrows; a linkage without masses gets 1 kg on each link (uniform bars) and
// gravity, so there is something to solve. --wander scales the hand's wander around the joint
// (±12 px across, ±8 px up and down): 1.3 takes the Watt II into a rocking crank and back
// twice. --trace prints a line per move. --census prints, per widget class, the time its
// repaints took and the layout requests it got per move (and skips the worst case, whose
// whole-window repaint would swamp the count); with --trace, also for each move. --threading
// gui sweeps every edit in the GUI thread, for a profiler (callgrind counts instructions, which
// the host's speed does not change). The older
// form `linkwright_gui_benchmark [moves] [example]` still works.

#include "ui/canvas/linkage_view.h"
#include "ui/document/force_results.h"
#include "ui/document/mechanism_document.h"
#include "ui/geometry.h"
#include "ui/main_window.h"
#include "ui/plots/plot_panel.h"
#include "ui/settings.h"

#include "kinematics/design/design.h"
#include "kinematics/model/fourbar.h"

#include <QApplication>
#include <QTest>

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace {

// Times every top-level event the GUI thread handles; events sent from inside a handler count
// with it. With a census it also adds up, per widget class, the time its paint events took and
// the layout requests it was sent: what a move makes Qt repaint and lay out again.
class TimedApplication : public QApplication {
public:
  using QApplication::QApplication;
  struct WidgetCensus {
    double paintMs = 0.0;
    int layouts = 0;
  };

  bool notify(QObject* receiver, QEvent* event) override {
    // Read before: a deferred delete destroys the receiver inside notify.
    const auto type = event->type();
    const char* className = receiver->metaObject()->className();
    WidgetCensus* counted =
        m_censusOn && receiver->isWidgetType() && (type == QEvent::Paint || type == QEvent::LayoutRequest)
            ? &m_census[widgetName(receiver)]
            : nullptr;
    const bool top = m_depth++ == 0;
    const auto start = std::chrono::steady_clock::now();
    const bool handled = QApplication::notify(receiver, event);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    --m_depth;
    if (top && ms > m_longest) {
      m_longest = ms;
      m_longestWhat = std::string(className) + " event " + std::to_string(static_cast<int>(type));
    }
    if (counted != nullptr && type == QEvent::Paint) counted->paintMs += ms;
    else if (counted != nullptr) ++counted->layouts;
    return handled;
  }
  /// The longest event since the last call, ms.
  double takeLongest() { return std::exchange(m_longest, 0.0); }
  /// What it was: the receiver's class and the event type (QEvent::Type).
  const std::string& longestWhat() const { return m_longestWhat; }
  void startCensus() { m_censusOn = true; }
  const std::map<std::string, WidgetCensus>& census() const { return m_census; }
  /// One line: the classes that took 0.3 ms or more of paint, or got a layout request, since
  /// the last call (a move, with --trace --census).
  void printCensusSinceLast() {
    std::printf("  repainted:");
    for (const auto& [widget, c] : m_census) {
      const WidgetCensus& before = m_printed[widget];
      if (c.paintMs - before.paintMs >= 0.3 || c.layouts > before.layouts)
        std::printf(" [%s %.2f ms, %d layouts]", widget.c_str(), c.paintMs - before.paintMs,
                    c.layouts - before.layouts);
    }
    std::printf("\n");
    m_printed = m_census;
  }

private:
  // The widget's class and its parent's: "QLineEdit in QDoubleSpinBox".
  static std::string widgetName(QObject* widget) {
    std::string name = widget->metaObject()->className();
    if (const QObject* parent = widget->parent()) name += std::string(" in ") + parent->metaObject()->className();
    return name;
  }

  int m_depth = 0;
  double m_longest = 0.0;
  std::string m_longestWhat;
  bool m_censusOn = false;
  std::map<std::string, WidgetCensus> m_census;
  std::map<std::string, WidgetCensus> m_printed;  // the census at the last printCensusSinceLast
};

// CPU time of the calling thread, ms.
double threadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

double percentile(std::vector<double> values, double p) {
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(std::lround(p * static_cast<double>(values.size() - 1)));
  return values[index];
}

struct Options {
  int moves = 400;
  std::optional<std::string> example;
  linkwright::ui::SamplingQuality quality = linkwright::ui::SamplingQuality::Normal;
  bool forces = false;
  bool trace = false;   // a line per move
  double wander = 1.0;  // times the hand's wander of ±12 px across, ±8 px up and down
  bool census = false;  // what each widget class costs per move: paint time, layout requests
  // As the designer sweeps (Adaptive); GuiThread for a profiler, under which every sweep is
  // slow enough for Adaptive to send it to a worker.
  linkwright::ui::DisplaySweeper::Threading threading = linkwright::ui::DisplaySweeper::Threading::Adaptive;
};

std::optional<Options> parse(int argc, char** argv) {
  Options o;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--forces") o.forces = true;
    else if (arg == "--trace") o.trace = true;
    else if (arg == "--census") o.census = true;
    else if (arg == "--wander" && hasValue) o.wander = std::clamp(std::atof(argv[++i]), 0.1, 10.0);
    else if (arg == "--moves" && hasValue) o.moves = std::max(10, std::atoi(argv[++i]));
    else if (arg == "--example" && hasValue) o.example = argv[++i];
    else if (arg == "--threading" && hasValue) {
      const std::string t = argv[++i];
      if (t == "adaptive") o.threading = linkwright::ui::DisplaySweeper::Threading::Adaptive;
      else if (t == "gui") o.threading = linkwright::ui::DisplaySweeper::Threading::GuiThread;
      else return std::nullopt;
    } else if (arg == "--quality" && hasValue) {
      const std::string q = argv[++i];
      if (q == "draft") o.quality = linkwright::ui::SamplingQuality::Draft;
      else if (q == "normal") o.quality = linkwright::ui::SamplingQuality::Normal;
      else if (q == "precise") o.quality = linkwright::ui::SamplingQuality::Precise;
      else return std::nullopt;
    } else if (arg.rfind("--", 0) != 0 && positional == 0) {
      o.moves = std::max(10, std::atoi(arg.c_str()));
      ++positional;
    } else if (arg.rfind("--", 0) != 0 && positional == 1) {
      o.example = arg;
      ++positional;
    } else {
      return std::nullopt;
    }
  }
  return o;
}

// 1 kg on every link (a uniform bar about its midpoint) and gravity: forces to solve.
void giveMasses(linkwright::kinematics::Design& d) {
  for (const linkwright::kinematics::Link& link : d.mechanism.links) d.dynamics.links.push_back({link.name, 1.0});
  d.dynamics.loads.gravity = linkwright::kinematics::standardGravity();
}

const char* qualityName(linkwright::ui::SamplingQuality q) {
  switch (q) {
  case linkwright::ui::SamplingQuality::Draft: return "draft";
  case linkwright::ui::SamplingQuality::Normal: return "normal";
  case linkwright::ui::SamplingQuality::Precise: return "precise";
  }
  return "normal";
}

}  // namespace

int main(int argc, char** argv) {
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  TimedApplication app(argc, argv);
  QApplication::setOrganizationName("LinkwrightBenchmark");
  const auto options = parse(argc, argv);
  if (!options) {
    std::fprintf(stderr,
                 "usage: linkwright_gui_benchmark [--moves N] [--example NAME] [--quality draft|normal|precise] "
                 "[--forces] [--trace] [--census] [--wander F] [--threading adaptive|gui]\n");
    return 2;
  }
  const int moves = options->moves;

  linkwright::ui::MainWindow window;
  window.resize(1400, 880);
  window.show();
  QApplication::processEvents();
  auto* doc = window.document();
  doc->setSweepThreading(options->threading);  // Adaptive by default, as app/main.cpp does
  auto* canvas = window.canvas();
  const auto* forces = window.forces();
  auto design = linkwright::kinematics::designForExample(options->example.value_or("thesis-crank-rocker"));
  if (!design) {
    std::fprintf(stderr, "linkwright_gui_benchmark: no example named %s\n", options->example->c_str());
    return 2;
  }
  if (options->forces && design->dynamics.empty()) giveMasses(*design);
  doc->reset(*design);
  doc->setQuality(options->quality);
  if (options->forces) window.showForces();  // the Forces tab and the canvas's force arrows
  // The drag starts once the window has settled, as a user's does: the plots have told the
  // document their width (150 ms after the last resize; the samples shown follow it), the
  // first quality estimate has landed (a worker, a few hundred ms after loading) and the value
  // axes have settled.
  window.plots()->reportPlotWidth();
  QApplication::processEvents();
  if (!QTest::qWaitFor([&] { return !doc->qualityEstimatePending(); }, 60000))
    std::printf("the first quality estimate did not land within 60 s\n");
  QTest::qWait(linkwright::ui::PlotPanel::kDataSettleMs);
  QApplication::processEvents();
  const std::size_t dragged = doc->fourBar() ? doc->fourBar()->c.index : doc->mechanism().points.size() - 1;
  const std::string name = options->example.value_or("thesis-crank-rocker");
  std::printf(
      "%s, dragging %s, %s, %s: %zu samples shown; plots and canvas redrawn after every move; canvas at "
      "%.3f px per length unit; wander x%.2f\n",
      name.c_str(), doc->mechanism().points[dragged].name.c_str(), qualityName(options->quality),
      options->forces ? "forces" : "kinematics", doc->sweep().size(), canvas->transform().m11(), options->wander);

  const QPointF start = canvas->mapFromScene(linkwright::ui::toQt(doc->pose().position[dragged]));
  const long sweepsBefore = doc->sweepsRun();
  QTest::mousePress(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  if (options->census) app.startCensus();
  std::vector<double> total, solve, full, cpu, longest;
  total.reserve(static_cast<std::size_t>(moves));
  for (int i = 0; i < moves; ++i) {
    // Wander a few pixels around the start, as a hand does, staying assemblable.
    const QPoint to = (start + options->wander * QPointF(12.0 * std::sin(i * 0.1), 8.0 * std::cos(i * 0.13))).toPoint();
    app.takeLongest();
    const long sweeps0 = doc->sweepsRun();
    const double cpu0 = threadCpuMs();
    const auto t0 = std::chrono::steady_clock::now();
    QTest::mouseMove(canvas->viewport(), to);
    const auto t1 = std::chrono::steady_clock::now();
    // Qt's own path to the screen: deferred scene and chart updates, then the update request
    // that paints every dirty widget into the backing store and flushes it.
    QApplication::processEvents();
    QApplication::sendPostedEvents();
    QApplication::processEvents();
    // What went to a worker is drawn when it lands: the GUI thread serves events meanwhile.
    const auto pending = [&] { return doc->sweepPending() || doc->analysisPending() || forces->cyclePending(); };
    if (pending()) {
      while (pending()) QApplication::processEvents(QEventLoop::WaitForMoreEvents);
      QApplication::processEvents();
      QApplication::sendPostedEvents();
      QApplication::processEvents();
    }
    const auto t2 = std::chrono::steady_clock::now();
    cpu.push_back(threadCpuMs() - cpu0);
    const std::string longestWhat = app.longestWhat();
    longest.push_back(app.takeLongest());
    if (options->trace)
      std::printf("move %d: wall %.2f ms, GUI CPU %.2f ms, longest event %.2f ms (%s), handling %.2f ms, %ld sweeps\n",
                  i, std::chrono::duration<double, std::milli>(t2 - t0).count(), cpu.back(), longest.back(),
                  longestWhat.c_str(), std::chrono::duration<double, std::milli>(t1 - t0).count(),
                  doc->sweepsRun() - sweeps0);
    if (options->trace && options->census) app.printCensusSinceLast();
    if (!options->census) window.repaint();  // worst case: every widget of the window painted again
    const auto t3 = std::chrono::steady_clock::now();
    solve.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    total.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
    full.push_back(std::chrono::duration<double, std::milli>(t3 - t2).count() + solve.back());
  }
  QTest::mouseRelease(canvas->viewport(), Qt::LeftButton, Qt::NoModifier, start.toPoint());
  if (options->census) {
    std::printf("per move, by widget class (paint ms, layout requests):\n");
    std::vector<std::pair<std::string, TimedApplication::WidgetCensus>> rows(app.census().begin(), app.census().end());
    std::sort(rows.begin(), rows.end(),
              [](const auto& a, const auto& b) { return a.second.paintMs > b.second.paintMs; });
    for (const auto& [widget, c] : rows)
      if (c.paintMs / moves >= 0.005 || c.layouts > 0)
        std::printf("  %8.3f ms  %6.2f  %s\n", c.paintMs / moves, static_cast<double>(c.layouts) / moves,
                    widget.c_str());
  }
  // Once the drag stops, the quality estimate is measured (in a worker) and the axes settle:
  // the GUI thread must stay responsive meanwhile too.
  app.takeLongest();
  const auto settleStart = std::chrono::steady_clock::now();
  if (!QTest::qWaitFor([&] { return !doc->qualityEstimatePending(); }, 60000))
    std::printf("the quality estimate did not land within 60 s\n");
  const double settleMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - settleStart).count();
  const double settleLongest = app.takeLongest();
  std::printf("moves: %d, undo steps: %d, sweeps: %.2f per move\n", moves, doc->undoStack()->count(),
              static_cast<double>(doc->sweepsRun() - sweepsBefore) / moves);
  std::printf("drag handling (core solve + document + item updates): median %.2f ms, p95 %.2f ms\n",
              percentile(solve, 0.5), percentile(solve, 0.95));
  std::printf("drag to redraw (handling + Qt's repaint of what changed): median %.2f ms, p95 %.2f ms, max %.2f ms\n",
              percentile(total, 0.5), percentile(total, 0.95), *std::max_element(total.begin(), total.end()));
  if (!options->census)
    std::printf("worst case (handling + whole window repainted):        median %.2f ms, p95 %.2f ms\n",
                percentile(full, 0.5), percentile(full, 0.95));
  std::printf("GUI thread's CPU time per move (handling + repaint):   median %.2f ms, p95 %.2f ms, max %.2f ms\n",
              percentile(cpu, 0.5), percentile(cpu, 0.95), *std::max_element(cpu.begin(), cpu.end()));
  std::printf("longest single event of the GUI thread per move:      median %.2f ms, p95 %.2f ms, max %.2f ms\n",
              percentile(longest, 0.5), percentile(longest, 0.95), *std::max_element(longest.begin(), longest.end()));
  std::printf(
      "after the drag: the quality estimate landed %.0f ms after release; longest GUI event meanwhile %.2f ms\n",
      settleMs, settleLongest);
  std::vector<std::size_t> slowest(total.size());
  for (std::size_t i = 0; i < slowest.size(); ++i) slowest[i] = i;
  std::sort(slowest.begin(), slowest.end(), [&](std::size_t a, std::size_t b) { return total[a] > total[b]; });
  std::printf("slowest moves (index: wall, GUI CPU ms):");
  for (std::size_t i = 0; i < std::min<std::size_t>(5, slowest.size()); ++i)
    std::printf(" %zu: %.1f, %.1f;", slowest[i], total[slowest[i]], cpu[slowest[i]]);
  std::printf("\none frame at 60 Hz: 16.67 ms\n");
  std::printf("RESULT %s %s %s handling %.2f %.2f %.2f redraw %.2f %.2f %.2f cpu %.2f %.2f %.2f event %.2f %.2f %.2f\n",
              name.c_str(), qualityName(options->quality), options->forces ? "forces" : "kinematics",
              percentile(solve, 0.5), percentile(solve, 0.95), *std::max_element(solve.begin(), solve.end()),
              percentile(total, 0.5), percentile(total, 0.95), *std::max_element(total.begin(), total.end()),
              percentile(cpu, 0.5), percentile(cpu, 0.95), *std::max_element(cpu.begin(), cpu.end()),
              percentile(longest, 0.5), percentile(longest, 0.95), *std::max_element(longest.begin(), longest.end()));
  return 0;
}
