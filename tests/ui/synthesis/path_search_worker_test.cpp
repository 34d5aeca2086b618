// Path generation from the synthesis panel (ui/synthesis/path_search_worker.h): the worker's best
// candidate equals a synchronous call of the core with the same request, its progress reaches
// the progress bar, Cancel returns early marked cancelled and leaves the document alone, and a
// newer search supersedes an older one.

#include "ui/synthesis/path_search_worker.h"
#include "ui/synthesis/candidate_table.h"
#include "ui/synthesis/synthesis_panel.h"
#include "ui/synthesis/target_forms.h"
#include "ui/synthesis/target_table.h"

#include "ui/document/mechanism_document.h"

#include "tests/support/catch.h"

#include <QApplication>
#include <QDeadlineTimer>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

using namespace linkwright;
namespace k = kinematics;
using Problem = ui::SynthesisProblem;

namespace {

// Processes events until `done` holds. The deadline only keeps a broken build from hanging:
// it is not a speed requirement (a Debug build under a sanitizer may take its time).
template <typename Done>
bool waitFor(Done done) {
  const QDeadlineTimer deadline(600'000);
  while (!done() && !deadline.hasExpired()) {
    QApplication::processEvents(QEventLoop::AllEvents, 50);
    QTest::qSleep(5);
  }
  return done();
}

}  // namespace

TEST_CASE("the worker's best path candidate is the one a synchronous call finds", "[ui][synthesis][path]") {
  ui::MechanismDocument doc;
  ui::SynthesisPanel panel(&doc, nullptr);
  panel.setProblem(Problem::Path);
  panel.pathForm()->startsBox()->setValue(12);
  const auto request = panel.pathForm()->request();
  REQUIRE(request.ok());
  CHECK(request->target.points.size() == 6);
  CHECK(request->options.starts == 12);

  panel.startPathSearch();
  CHECK(panel.pathSearch()->isRunning());
  CHECK(panel.cancelButton()->isEnabled());
  REQUIRE(waitFor([&] { return !panel.pathSearch()->isRunning(); }));
  CHECK_FALSE(panel.cancelButton()->isEnabled());
  REQUIRE(panel.refusalMessage().isEmpty());
  REQUIRE(panel.outcome().has_value());

  const auto direct = k::synthesisePath(request->target, request->options, k::DefectBounds{});
  REQUIRE(direct.ok());
  REQUIRE_FALSE(direct->candidates.empty());
  REQUIRE(panel.outcome()->rows.size() == direct->candidates.size());
  for (std::size_t i = 0; i < direct->candidates.size(); ++i) {
    CAPTURE(i);
    CHECK(panel.outcome()->rows[i].candidate.design == direct->candidates[i].candidate.design);
    CHECK(panel.outcome()->rows[i].candidate.error == direct->candidates[i].worstDistance);
    CHECK(panel.outcome()->rows[i].previewInput == direct->candidates[i].crankAngles.front());
  }
  CHECK(panel.candidates()->rowCount() == static_cast<int>(direct->candidates.size()));
  // Every start was reported to the progress bar before the result arrived.
  CHECK(panel.progressBar()->maximum() == 12);
  CHECK(panel.progressBar()->value() == 12);
}

TEST_CASE("Cancel stops a path search early, marked cancelled, and the document is untouched",
          "[ui][synthesis][path]") {
  ui::MechanismDocument doc;
  const k::Design before = doc.design();
  ui::SynthesisPanel panel(&doc, nullptr);
  panel.setProblem(Problem::Path);
  panel.pathForm()->startsBox()->setValue(100000);
  std::optional<ui::PathSearchResult> got;
  QObject::connect(panel.pathSearch(), &ui::PathSearchWorker::finished,
                   [&](const ui::PathSearchResult& result) { got = result; });
  panel.startPathSearch();
  REQUIRE(panel.pathSearch()->isRunning());
  QTest::mouseClick(panel.cancelButton(), Qt::LeftButton);
  REQUIRE(waitFor([&] { return got.has_value(); }));
  REQUIRE(got->synthesis.has_value());
  CHECK(got->synthesis->cancelled);
  CHECK(got->synthesis->startsRun < 100000);
  CHECK(panel.refusalMessage().isEmpty());
  // The linkage is untouched; only the targets typed (the starts) are kept, in one step.
  CHECK(doc.design().mechanism == before.mechanism);
  CHECK(doc.undoStack()->count() == 1);
  CHECK(doc.design().synthesis->pathSearch.starts == 100000);
  CHECK(panel.outcome().has_value());  // what was found before the cancel is listed
}

TEST_CASE("a newer path search supersedes an older one", "[ui][synthesis][path]") {
  ui::PathSearchWorker search;
  int results = 0;
  std::optional<ui::PathSearchResult> got;
  QObject::connect(&search, &ui::PathSearchWorker::finished, [&](const ui::PathSearchResult& result) {
    ++results;
    got = result;
  });
  ui::PathRequest request;
  request.target.points = {{59.8, 49.0}, {37.9, 57.6}, {10.7, 46.4}, {2.7, 25.0}, {26.1, 16.2}, {51.4, 27.0}};
  request.options.starts = 100000;
  search.start(request, {});
  request.options.starts = 3;
  search.start(request, {});
  REQUIRE(waitFor([&] { return !search.isRunning(); }));
  REQUIRE(got.has_value());
  CHECK(got->request.options.starts == 3);
  REQUIRE(got->synthesis.has_value());
  CHECK_FALSE(got->synthesis->cancelled);
  CHECK(got->synthesis->startsRun == 3);
  // The older search, cancelled, ends without a word.
  QTest::qWait(50);
  CHECK(results == 1);
}

TEST_CASE("a path request with too few points is refused naming the targets", "[ui][synthesis][path]") {
  ui::MechanismDocument doc;
  ui::SynthesisPanel panel(&doc, nullptr);
  panel.setProblem(Problem::Path);
  panel.pathForm()->points()->setRows({{0, 0, 0}, {1, 0, 0}, {2, 1, 0}});
  panel.startPathSearch();
  CHECK_FALSE(panel.pathSearch()->isRunning());
  CHECK(panel.refusalMessage().contains("Targets"));
  CHECK(panel.refusalMessage().contains("got 3"));
}
