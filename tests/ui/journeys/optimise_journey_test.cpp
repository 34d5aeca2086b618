// Edit ▸ Optimise… as a person uses it, on the thesis crank-rocker: the window opened from the
// menu, the rocker's peak α chosen, Run, the progress bar filling while it runs in the
// background, then Accept: the design is the core's result for the same request, the chart
// holds the objective's curve before and after; Ctrl+Z restores the start exactly. Cancel
// mid-run leaves the design as it was; an edit of the design while a result is shown drops it,
// and one while it runs stops the run.
// After every step the journeys' invariants hold.

#include "tests/ui/journeys/journey.h"

#include "ui/document/mechanism_document.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/optimise_window.h"

#include "kinematics/design/design.h"
#include "kinematics/tune/optimise_linkage.h"
#include "tests/support/catch.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>

using namespace linkwright;
namespace k = linkwright::kinematics;

namespace {

ui::OptimiseWindow* openOptimise(test::Journey& journey) {
  journey.menu({"Edit", "Optimise"});
  auto* window = journey.window().findChild<ui::OptimiseWindow*>();
  REQUIRE(window != nullptr);
  REQUIRE(window->isVisible());
  return window;
}

// Runs with the fields as they are and waits for the result.
void runAndWait(test::Journey& journey, ui::OptimiseWindow* window) {
  QSignalSpy ended(window, &ui::OptimiseWindow::runEnded);
  const QPoint runAt = window->runButton()->mapTo(window, QPoint());
  QTest::mouseClick(window->runButton(), Qt::LeftButton);
  CHECK(window->running());
  // The chart's place is kept while it runs: Run and Cancel stay under the pointer.
  QCoreApplication::processEvents();
  CHECK(window->runButton()->mapTo(window, QPoint()) == runAt);
  CHECK(window->cancelButton()->isEnabled());
  CHECK_FALSE(window->runButton()->isEnabled());
  REQUIRE(ended.wait(60000));
  journey.settle();
}

}  // namespace

TEST_CASE("Edit > Optimise runs in the background, Accept applies the core's result and Ctrl+Z undoes it",
          "[journey][optimise]") {
  test::Journey journey;
  journey.example("thesis-crank-rocker");
  ui::MechanismDocument* document = journey.window().document();
  const k::Design start = document->design();
  ui::OptimiseWindow* window = openOptimise(journey);
  journey.check("Edit ▸ Optimise…");
  window->objectiveBox()->setCurrentIndex(0);  // peak |α|
  window->linkBox()->setCurrentText("rocker");
  CHECK_FALSE(window->acceptButton()->isEnabled());

  runAndWait(journey, window);
  REQUIRE(window->result().has_value());
  // The simplexes shrank before the budget was spent: the bar is full all the same.
  CHECK(window->result()->evaluations < window->evaluationsField()->value());
  CHECK(window->progressBar()->value() == window->progressBar()->maximum());
  CHECK(window->acceptButton()->isEnabled());
  CHECK(document->design() == start);  // nothing changes before Accept
  const auto core = k::optimiseLinkage(start, window->request().value());
  REQUIRE(core.ok());
  CHECK(window->result()->design == core->design);
  CHECK(window->result()->after < window->result()->before);
  CHECK(window->summaryText().contains("peak |α| of rocker"));
  // The chart: before and after, every sample, the core's curves (α in rad/s²).
  REQUIRE(window->chart()->isVisible());
  CHECK(window->chart()->samples(0).size() == static_cast<qsizetype>(core->curveBefore.y.size()));
  CHECK(window->chart()->samples(1).size() == static_cast<qsizetype>(core->curveAfter.y.size()));
  CHECK(window->chart()->samples(1).front().y() == core->curveAfter.y.front());
  journey.check("optimised");

  const int undoSteps = document->undoStack()->count();
  QTest::mouseClick(window->acceptButton(), Qt::LeftButton);
  journey.settle();
  CHECK(document->design() == core->design);
  CHECK(document->undoStack()->count() == undoSteps + 1);  // one undoable edit
  CHECK_FALSE(window->acceptButton()->isEnabled());
  journey.check("accepted");

  // Back in the main window (the optimise window closed), Ctrl+Z.
  window->close();
  journey.key(Qt::Key_Z, Qt::ControlModifier);
  CHECK(document->design() == start);
  // The window no longer tells of the edit undone, nor shows its curves.
  CHECK_FALSE(window->summaryText().contains("Applied"));
  CHECK(window->summaryText().contains("Run again"));
  CHECK_FALSE(window->chart()->isVisible());
  journey.check("Ctrl+Z");
}

TEST_CASE("Cancel mid-run leaves the design, and an edit drops a result made for the design before",
          "[journey][optimise]") {
  test::Journey journey;
  journey.example("thesis-crank-rocker");
  ui::MechanismDocument* document = journey.window().document();
  const k::Design start = document->design();
  ui::OptimiseWindow* window = openOptimise(journey);
  window->objectiveBox()->setCurrentIndex(1);  // the worst transmission angle
  window->evaluationsField()->setValue(100000);

  // Cancel at once: the run (a few hundred designs at least) is still going.
  QSignalSpy ended(window, &ui::OptimiseWindow::runEnded);
  QTest::mouseClick(window->runButton(), Qt::LeftButton);
  REQUIRE(window->running());
  QTest::mouseClick(window->cancelButton(), Qt::LeftButton);
  REQUIRE((ended.count() == 1 || ended.wait(30000)));
  journey.settle();
  CHECK_FALSE(window->running());
  CHECK(document->design() == start);
  // The best found before the cancel is shown; Discard leaves the design.
  REQUIRE(window->result().has_value());
  CHECK(window->result()->cancelled);
  CHECK(window->result()->evaluations < 200);
  CHECK(window->progressBar()->value() < window->progressBar()->maximum());  // not "100 %"
  QTest::mouseClick(window->discardButton(), Qt::LeftButton);
  CHECK_FALSE(window->result().has_value());
  CHECK(document->design() == start);
  journey.check("cancelled and discarded");

  // A short run, then an edit of the design: the result was for the design before.
  window->evaluationsField()->setValue(60);
  runAndWait(journey, window);
  REQUIRE(window->result().has_value());
  k::Design edited = start;
  edited.omega = 2.0;
  REQUIRE_FALSE(document->edit(edited, "speed"));
  journey.settle();
  CHECK_FALSE(window->result().has_value());
  CHECK_FALSE(window->acceptButton()->isEnabled());
  CHECK_FALSE(window->chart()->isVisible());
  CHECK(window->summaryText().contains("dropped"));
  journey.check("edited while a result was shown");

  // An edit while it runs stops the run: no result comes for the design before, and Run is
  // offered again once the worker has stopped.
  window->evaluationsField()->setValue(100000);
  QTest::mouseClick(window->runButton(), Qt::LeftButton);
  REQUIRE(window->running());
  REQUIRE_FALSE(document->edit(start, "speed back"));
  CHECK(window->summaryText().contains("the run was stopped"));
  for (int i = 0; i < 3000 && window->running(); ++i) QTest::qWait(10);
  journey.settle();
  CHECK_FALSE(window->running());
  CHECK_FALSE(window->result().has_value());
  CHECK(window->runButton()->isEnabled());
  CHECK_FALSE(window->cancelButton()->isEnabled());
  CHECK(document->design() == start);
  journey.check("edited while running");
}
