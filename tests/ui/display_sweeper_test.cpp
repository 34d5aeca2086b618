// The document's displayed sweep in a worker (display_sweeper.h): a drag's sweep of a Newton
// six-bar at Precise lands equal, to the last bit, to the one the GUI thread computes; the
// last sweep stays shown meanwhile; a newer edit cancels the older sweep and only the newest
// lands; a sweep of another shape (other samples, quantities or structure) is never deferred;
// and the core's sweep stops when told to. A drag's design grid (the analysis's crank range
// and gaps) lands from a worker too, equal to the GUI thread's analysis.
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <QSignalSpy>
#include <QTest>

#include "tests/support/catch.h"

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
  CHECK(inWorker.pose() == inGui.pose());                                // the pose follows at once
  CHECK(inWorker.analysis().inputRange == inGui.analysis().inputRange);  // a full turn before and after

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

namespace {

// The Watt II with E's second bar (to O6) `by` longer: -20 mm leaves the crank three
// ranges, still holding 0°; -25 mm leaves it two, without 0°; +200 mm assembles nowhere.
k::Design wattWithBar(const k::Design& watt, double by) {
  k::Design d = watt;
  std::get<k::RrrPoint>(d.mechanism.points.back().definition).secondLength += by;
  return d;
}

void openWatt(MechanismDocument& doc, Threading threading) {
  doc.setSweepThreading(threading);
  doc.reset(*k::designForExample("watt-ii"));
}

}  // namespace

TEST_CASE("a drag's design grid lands from a worker, and the analysis then equals the GUI thread's",
          "[document][sweep][worker]") {
  MechanismDocument inWorker;
  MechanismDocument inGui;
  openWatt(inWorker, Threading::Adaptive);
  openWatt(inGui, Threading::GuiThread);
  REQUIRE(inWorker.analysis().inputRange.fullRotation);
  REQUIRE_FALSE(inWorker.analysisPending());  // a new document analyses at once

  QSignalSpy spy(&inWorker, &MechanismDocument::changed);
  const long sweepsBefore = inWorker.sweepsRun();
  REQUIRE_FALSE(inWorker.edit(wattWithBar(inWorker.design(), -20.0), "bar", kDrag));
  REQUIRE_FALSE(inGui.edit(wattWithBar(inGui.design(), -20.0), "bar", kDrag));
  REQUIRE(inGui.analysis().inputRange.ranges.size() == 3);
  // Accepted without its grid (it assembles at the crank angle shown); the grid is in a worker
  // and the analysis keeps the last grid's range meanwhile. The pose follows at once.
  CHECK(inWorker.analysisPending());
  CHECK_FALSE(inGui.analysisPending());
  CHECK(inWorker.sweepsRun() - sweepsBefore == 2);  // the display sweep and the grid, once each
  CHECK(inWorker.analysis().inputRange.fullRotation);
  CHECK(inWorker.pose() == inGui.pose());
  CHECK(countOf(spy, Change::Analysis) == 0);

  inWorker.waitForSweep();
  CHECK_FALSE(inWorker.analysisPending());
  CHECK(inWorker.analysis().inputRange == inGui.analysis().inputRange);
  CHECK(inWorker.analysis().notAssembled == inGui.analysis().notAssembled);
  CHECK(inWorker.crankAngle() == inGui.crankAngle());
  CHECK(countOf(spy, Change::Analysis) == 1);  // the panel and the canvas redraw the range
  CHECK(countOf(spy, Change::Motion) == 1);    // the edit's own: 0° is still in range
}

TEST_CASE("a drag's grid that changes no range lands unannounced", "[document][sweep][worker]") {
  MechanismDocument doc;
  openWatt(doc, Threading::Adaptive);
  QSignalSpy spy(&doc, &MechanismDocument::changed);
  REQUIRE_FALSE(doc.edit(wattWithBar(doc.design(), 10.0), "bar", kDrag));
  CHECK(doc.analysisPending());
  doc.waitForSweep();
  CHECK(doc.analysis().inputRange.fullRotation);
  CHECK(countOf(spy, Change::Analysis) == 0);
}

TEST_CASE("a drag's design that does not assemble at the crank angle shown is checked on its whole grid at once",
          "[document][sweep][worker]") {
  MechanismDocument inWorker;
  MechanismDocument inGui;
  openWatt(inWorker, Threading::Adaptive);
  openWatt(inGui, Threading::GuiThread);
  REQUIRE_FALSE(inWorker.edit(wattWithBar(inWorker.design(), -25.0), "bar", kDrag));
  REQUIRE_FALSE(inGui.edit(wattWithBar(inGui.design(), -25.0), "bar", kDrag));
  CHECK_FALSE(inWorker.analysisPending());
  CHECK(inWorker.analysis().inputRange == inGui.analysis().inputRange);
  CHECK(inWorker.crankAngle() == inGui.crankAngle());  // clamped out of the gap at once
  CHECK(inWorker.crankAngle() > 6.0);
  CHECK(inWorker.poseStatus() == k::PoseStatus::Ok);

  // One that assembles nowhere is refused as before, and nothing changes.
  const k::Design kept = inWorker.design();
  const auto why = inWorker.edit(wattWithBar(kept, 200.0), "bar", kDrag);
  REQUIRE(why);
  CHECK(why->contains("cannot be assembled at any crank angle"));
  CHECK(inWorker.design() == kept);
  CHECK_FALSE(inWorker.analysisPending());
}

TEST_CASE("a grid in flight never lands on a later design", "[document][sweep][worker]") {
  MechanismDocument doc;
  openWatt(doc, Threading::Adaptive);
  REQUIRE_FALSE(doc.edit(wattWithBar(doc.design(), -20.0), "bar", kDrag));
  REQUIRE(doc.analysisPending());
  doc.reset(*k::designForExample("thesis-crank-rocker"));
  CHECK_FALSE(doc.analysisPending());
  QTest::qWait(50);  // a stray landing would arrive through the event loop
  doc.waitForSweep();
  CHECK(doc.analysis().inputRange.fullRotation);
  CHECK(doc.analysis().grashof.has_value());  // the four-bar's analysis, not the Watt II's grid
}
