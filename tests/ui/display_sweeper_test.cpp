// The document's displayed sweep in a worker (display_sweeper.h): a drag's sweep of a Newton
// six-bar at Precise lands equal, to the last bit, to the one the GUI thread computes; the
// last sweep stays shown meanwhile; a newer edit cancels the older sweep and only the newest
// lands; a sweep of another shape (other samples, quantities or structure) is never deferred;
// and the core's sweep stops when told to.
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <QSignalSpy>
#include <QTest>

#include <catch2/catch.hpp>

#include <atomic>
#include <memory>

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

using Threading = DisplaySweeper::Threading;

// The Newton six-bar at Precise (3601 samples), swept where `threading` says.
void openStephenson(MechanismDocument& doc, Threading threading) {
  doc.setSweepThreading(threading);
  doc.reset(*k::designForExample("stephenson-ii"));
  doc.setQuality(SamplingQuality::Precise);
}

// The design with its first bar `by` longer (a drag of one of its joints, in effect).
k::Design longerBar(const k::Design& design, double by) {
  k::Design d = design;
  d.mechanism.constraints.front().length += by;
  return d;
}

const MergeKey kDrag{ContinuousEdit::DragPoint, 1, 0};

// How many of the changed() signals `spy` caught carry `change`.
int countOf(const QSignalSpy& spy, Change change) {
  int n = 0;
  for (const QList<QVariant>& args : spy) n += (args.front().value<Changes>() & change) ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("a drag's sweep in a worker lands equal to the GUI thread's, the last one shown meanwhile",
          "[document][sweep][worker]") {
  MechanismDocument inWorker;
  MechanismDocument inGui;
  openStephenson(inWorker, Threading::Worker);
  openStephenson(inGui, Threading::GuiThread);
  REQUIRE_FALSE(inWorker.sweepPending());  // a new document is swept at once
  REQUIRE(inWorker.sweep() == inGui.sweep());
  REQUIRE(inWorker.sweep().size() > 3000);
  const k::SweepResult before = inWorker.sweep();

  QSignalSpy spy(&inWorker, &MechanismDocument::changed);
  REQUIRE_FALSE(inWorker.edit(longerBar(inWorker.design(), 0.5), "bar", kDrag));
  REQUIRE_FALSE(inGui.edit(longerBar(inGui.design(), 0.5), "bar", kDrag));
  CHECK(inWorker.sweepPending());
  CHECK_FALSE(inGui.sweepPending());
  CHECK(inWorker.sweep() == before);  // the views keep reading the last sweep
  CHECK(inWorker.design() == inGui.design());
  CHECK(inWorker.pose() == inGui.pose());  // the pose and the analysis follow at once
  CHECK(inWorker.analysis().inputRange == inGui.analysis().inputRange);

  inWorker.waitForSweep();
  CHECK_FALSE(inWorker.sweepPending());
  CHECK(countOf(spy, Change::Request) == 1);  // the views hear that it landed
  CHECK(inWorker.sweep() == inGui.sweep());
  CHECK_FALSE(inWorker.sweep() == before);
}

TEST_CASE("by default every edit's sweep is there when the edit returns", "[document][sweep][worker]") {
  MechanismDocument doc;
  doc.reset(*k::designForExample("stephenson-ii"));
  doc.setQuality(SamplingQuality::Precise);  // a sweep of milliseconds: Adaptive would defer the next
  REQUIRE_FALSE(doc.edit(longerBar(doc.design(), 0.5), "bar", kDrag));
  CHECK_FALSE(doc.sweepPending());
  MechanismDocument check;
  openStephenson(check, Threading::GuiThread);
  REQUIRE_FALSE(check.edit(doc.design(), "bar"));
  CHECK(doc.sweep() == check.sweep());
}

TEST_CASE("a newer edit cancels the worker's older sweep, and only the newest lands", "[document][sweep][worker]") {
  MechanismDocument doc;
  openStephenson(doc, Threading::Worker);
  const k::SweepResult first = doc.sweep();
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  // Three frames of a drag before the event loop runs again: each starts a sweep and cancels
  // the one before.
  for (int frame = 1; frame <= 3; ++frame) {
    REQUIRE_FALSE(doc.edit(longerBar(doc.design(), 0.2), "bar", kDrag));
    CHECK(doc.sweepPending());
    CHECK(doc.sweep() == first);
  }
  CHECK(countOf(spy, Change::Request) == 0);
  doc.waitForSweep();
  // The cancelled sweeps never land; the event loop has nothing left to deliver either.
  QCoreApplication::processEvents();
  CHECK(countOf(spy, Change::Request) == 1);
  MechanismDocument check;
  openStephenson(check, Threading::GuiThread);
  REQUIRE_FALSE(check.edit(doc.design(), "bar"));
  CHECK(doc.sweep() == check.sweep());
}

TEST_CASE("a worker's sweep lands through the event loop, and undo's sweep too", "[document][sweep][worker]") {
  MechanismDocument doc;
  openStephenson(doc, Threading::Worker);
  const k::SweepResult first = doc.sweep();
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  REQUIRE_FALSE(doc.edit(longerBar(doc.design(), 0.5), "bar", kDrag));
  REQUIRE(QTest::qWaitFor([&] { return !doc.sweepPending(); }, 60000));
  CHECK(countOf(spy, Change::Request) == 1);
  CHECK_FALSE(doc.sweep() == first);
  doc.undoStack()->undo();
  doc.waitForSweep();
  CHECK(doc.sweep() == first);
}

TEST_CASE("a sweep of another shape is never left to a worker", "[document][sweep][worker]") {
  MechanismDocument doc;
  openStephenson(doc, Threading::Worker);
  SECTION("another crank range: other samples") {
    k::Design d = doc.design();
    d.toDeg -= 10.0;
    REQUIRE_FALSE(doc.edit(d, "range"));
    CHECK_FALSE(doc.sweepPending());
    CHECK(doc.sweep().inputAngle.back() == Approx(k::degToRad(d.toDeg)));
  }
  SECTION("another quality, request or width") {
    doc.setQuality(SamplingQuality::Normal);
    CHECK_FALSE(doc.sweepPending());
    CHECK(doc.sweep().size() == doc.displaySpec().samples);
    k::SolveRequest request = doc.request();
    request.accelerations = !request.accelerations;
    doc.setRequest(request);
    CHECK_FALSE(doc.sweepPending());
    CHECK(doc.sweep().request.accelerations == request.accelerations);
  }
  SECTION("another example") {
    doc.reset(*k::designForExample("watt-ii"));
    CHECK_FALSE(doc.sweepPending());
    CHECK(doc.sweep().position.size() == doc.mechanism().points.size());
  }
}

TEST_CASE("a document destroyed with a sweep in flight stops it and waits for it", "[document][sweep][worker]") {
  auto doc = std::make_unique<MechanismDocument>();
  openStephenson(*doc, Threading::Worker);
  REQUIRE_FALSE(doc->edit(longerBar(doc->design(), 0.5), "bar", kDrag));
  CHECK(doc->sweepPending());
  doc.reset();  // no thread outlives it (a sanitizer run would catch one writing freed memory)
  QCoreApplication::processEvents();
}

TEST_CASE("the core's sweep stops when cancelled, and says so", "[document][sweep][worker]") {
  const k::Design design = *k::designForExample("stephenson-ii");
  const k::SweepSpec spec = k::designSweepSpec(design);
  k::SweepResult out;
  const std::atomic<bool> cancelled{true};
  const auto stopped = k::sweepInto(design.mechanism, spec, {}, out, &cancelled);
  REQUIRE(stopped);
  CHECK(stopped->code == k::ErrorCode::Cancelled);
  const std::atomic<bool> running{false};
  CHECK_FALSE(k::sweepInto(design.mechanism, spec, {}, out, &running));
  CHECK(out == k::sweep(design.mechanism, spec, {}).value());
}
