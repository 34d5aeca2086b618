// ForceResults: solves nothing while disabled; while enabled, its columns are exactly the
// core's sweepForces on the sweep it names, a crank move re-solves the pose forces only, and a
// design without masses or with an unknown length unit says so. In a worker thread the cycle
// is the same to the last bit, a newer change cancels an older solve, and the last cycle
// stays shown until the new one lands.
#include "ui/document/force_results.h"

#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"

#include <QSignalSpy>

#include "tests/support/catch.h"

using namespace linkwright::ui;
namespace k = linkwright::kinematics;

namespace {

k::Design funsho() { return *k::designForExample("funsho-fourbar"); }
const k::LinkageDynamics& dynamicsOf(const MechanismDocument& doc) { return doc.design().dynamics; }

}  // namespace

TEST_CASE("ForceResults computes nothing while disabled", "[forces][results]") {
  MechanismDocument doc;
  doc.reset(funsho());
  ForceResults forces(&doc);
  QSignalSpy spy(&forces, &ForceResults::changed);
  doc.setCrankAngle(1.0);
  doc.edit(doc.design(), "noop");  // an unchanged design: nothing happens either way
  CHECK(forces.state() == ForceResults::State::Disabled);
  CHECK(forces.cycleForces() == nullptr);
  CHECK(forces.poseForces() == nullptr);
  CHECK(forces.bodies() == nullptr);
  CHECK(spy.isEmpty());
  forces.setEnabled(true);
  CHECK(forces.cycleForces() != nullptr);
  forces.setEnabled(false);
  CHECK(forces.cycleForces() == nullptr);
  CHECK(forces.state() == ForceResults::State::Disabled);
}

TEST_CASE("with funsho-fourbar the torque column is the core's sweepForces on the same sweep", "[forces][results]") {
  MechanismDocument doc;
  doc.reset(funsho());
  ForceResults forces(&doc);
  SECTION("on the document's sweep, once its request asks for accelerations") {
    doc.setRequest(ForceResults::forcesRequest(doc.request()));
    forces.setEnabled(true);
    REQUIRE(forces.state() == ForceResults::State::Ok);
    CHECK_FALSE(forces.usesOwnSweep());
    // A copy of the document's sweep, so that a worker can read it while the document moves on.
    CHECK(forces.cycleSweep()->inputAngle == doc.sweep().inputAngle);
    CHECK(forces.cycleSweep()->acceleration == doc.sweep().acceleration);
    const k::ForceSweep expected = k::sweepForces(doc.mechanism(), dynamicsOf(doc), doc.sweep()).value();
    CHECK(forces.cycleForces()->driveTorque == expected.driveTorque);
    CHECK(forces.cycleForces()->revolute == expected.revolute);
    CHECK(forces.message().isEmpty());
  }
  SECTION("on a sweep of its own over the same grid while the document's lacks accelerations") {
    doc.setRequest({false, false});
    forces.setEnabled(true);
    REQUIRE(forces.state() == ForceResults::State::Ok);
    CHECK(forces.usesOwnSweep());
    const k::SweepResult own = k::sweep(doc.mechanism(), doc.displaySpec(), ForceResults::forcesRequest({})).value();
    CHECK(forces.cycleSweep()->inputAngle == doc.sweep().inputAngle);
    const k::ForceSweep expected = k::sweepForces(doc.mechanism(), dynamicsOf(doc), own).value();
    CHECK(forces.cycleForces()->driveTorque == expected.driveTorque);
  }
  CHECK(forces.peakJointForce() > 0.0);
}

TEST_CASE("a crank move re-solves the pose forces only, as forcesAtPose gives them", "[forces][results]") {
  MechanismDocument doc;
  doc.reset(funsho());
  ForceResults forces(&doc);
  forces.setEnabled(true);
  const k::ForceSweep* cycle = forces.cycleForces();
  QSignalSpy spy(&forces, &ForceResults::changed);
  doc.setCrankAngle(0.7);
  REQUIRE(spy.size() == 1);
  CHECK(spy.front().front().toBool() == false);
  CHECK(forces.cycleForces() == cycle);
  REQUIRE(forces.poseForces() != nullptr);
  const k::PoseForces expected = k::forcesAtPose(doc.mechanism(), dynamicsOf(doc), doc.pose()).value();
  CHECK(forces.poseForces()->driveTorque == Approx(expected.driveTorque).epsilon(1e-12));
  CHECK(forces.poseForces()->revolute.size() == expected.revolute.size());
}

TEST_CASE("a design without masses or loads, or with an unknown unit, has no forces and says why",
          "[forces][results]") {
  MechanismDocument doc;  // the thesis crank-rocker: no dynamics
  ForceResults forces(&doc);
  forces.setEnabled(true);
  CHECK(forces.state() == ForceResults::State::NoDynamics);
  CHECK(forces.message().contains("no masses or loads"));
  // It points at where the masses go, the Forces tab's Links table (there is no Properties panel).
  CHECK(forces.message().contains("Links table"));
  CHECK_FALSE(forces.message().contains("Properties"));
  CHECK(forces.cycleForces() == nullptr);

  k::Design d = funsho();
  d.mechanism.lengthUnit = "furlong";
  if (!doc.validate(d)) {  // kinematics accept any unit label; forces need metres
    doc.reset(d);
    CHECK(forces.state() == ForceResults::State::Failed);
    CHECK(forces.message().contains("lengthUnit"));
    CHECK(forces.cycleForces() == nullptr);
  }
}

namespace {

// Every column of two force sweeps, compared exactly.
bool sameForces(const k::ForceSweep& a, const k::ForceSweep& b) {
  return a.status == b.status && a.revolute == b.revolute && a.normal == b.normal && a.moment == b.moment &&
         a.driveTorque == b.driveTorque && a.driveAlong == b.driveAlong && a.driveForce == b.driveForce &&
         a.jointTorque == b.jointTorque && a.shakingForce == b.shakingForce && a.shakingMoment == b.shakingMoment;
}

// The document's four-bar with its crank `mm` longer: one frame of a drag.
k::Design longerCrank(const MechanismDocument& doc, double mm) {
  k::Design d = doc.design();
  k::FourBarLengths lengths = doc.fourBar()->lengths;
  lengths.crank += mm;
  d.mechanism = k::withFourBarLengths(d.mechanism, *doc.fourBar(), lengths);
  return d;
}

}  // namespace

TEST_CASE("a cycle solved in a worker thread equals the one solved in the GUI thread", "[forces][results][worker]") {
  MechanismDocument doc;
  doc.reset(funsho());
  doc.setQuality(SamplingQuality::Precise);
  ForceResults inGui(&doc), inWorker(&doc);
  inGui.setThreading(ForceResults::Threading::GuiThread);
  inWorker.setThreading(ForceResults::Threading::Worker);
  inGui.setEnabled(true);
  inWorker.setEnabled(true);
  REQUIRE(inWorker.cyclePending());
  CHECK(inWorker.cycleForces() == nullptr);  // nothing solved yet, nothing shown
  QSignalSpy landed(&inWorker, &ForceResults::changed);
  inWorker.waitForCycle();
  CHECK_FALSE(inWorker.cyclePending());
  REQUIRE(landed.count() == 1);
  CHECK(landed.front().front().toBool());  // a whole cycle
  REQUIRE(inWorker.state() == ForceResults::State::Ok);
  CHECK(inWorker.cycleSweep()->inputAngle == inGui.cycleSweep()->inputAngle);
  CHECK(sameForces(*inWorker.cycleForces(), *inGui.cycleForces()));
  CHECK(inWorker.peakJointForce() == inGui.peakJointForce());
  CHECK(inWorker.cycleForces()->size() == doc.sweep().size());
}

TEST_CASE("a newer edit cancels the worker's older solve, the last cycle stays shown meanwhile",
          "[forces][results][worker]") {
  MechanismDocument doc;
  doc.reset(funsho());
  doc.setQuality(SamplingQuality::Precise);
  ForceResults forces(&doc);
  forces.setThreading(ForceResults::Threading::Worker);
  forces.setEnabled(true);
  forces.waitForCycle();
  const k::ForceSweep first = *forces.cycleForces();
  QSignalSpy spy(&forces, &ForceResults::changed);

  // Three frames of a drag before the event loop runs again: each starts a solve and cancels
  // the one before, and the views keep the first cycle and get only pose updates.
  for (int frame = 0; frame < 3; ++frame) {
    REQUIRE_FALSE(doc.edit(longerCrank(doc, 0.5), "crank", MergeKey{ContinuousEdit::DragPoint, 1, 0}));
    CHECK(forces.cyclePending());
    CHECK(sameForces(*forces.cycleForces(), first));
    REQUIRE(forces.poseForces() != nullptr);  // the pose forces follow each frame at once
  }
  REQUIRE(spy.count() == 3);
  for (const QList<QVariant>& args : spy) CHECK_FALSE(args.front().toBool());
  spy.clear();
  forces.waitForCycle();
  // Only the newest solve lands: one whole-cycle change, for the design as it is now.
  REQUIRE(spy.count() == 1);
  CHECK(spy.front().front().toBool());
  ForceResults check(&doc);
  check.setThreading(ForceResults::Threading::GuiThread);
  check.setEnabled(true);
  CHECK(sameForces(*forces.cycleForces(), *check.cycleForces()));
  CHECK_FALSE(sameForces(*forces.cycleForces(), first));
}

TEST_CASE("a worker's solve stops when cancelled, and the core says so", "[forces][results][worker]") {
  MechanismDocument doc;
  doc.reset(funsho());
  doc.setRequest(ForceResults::forcesRequest(doc.request()));
  const std::atomic<bool> cancelled{true};
  const auto stopped = k::sweepForces(doc.mechanism(), dynamicsOf(doc), doc.sweep(), &cancelled);
  REQUIRE_FALSE(stopped);
  CHECK(stopped.error().code == k::ErrorCode::Cancelled);
  const std::atomic<bool> running{false};
  CHECK(k::sweepForces(doc.mechanism(), dynamicsOf(doc), doc.sweep(), &running));
  // A ForceResults destroyed with a solve in flight stops it and waits for it.
  {
    ForceResults forces(&doc);
    forces.setThreading(ForceResults::Threading::Worker);
    forces.setEnabled(true);
    CHECK(forces.cyclePending());
  }
}

TEST_CASE("while the document's sweep is in a worker the cycle waits for it, then equals the GUI thread's",
          "[forces][results][worker]") {
  MechanismDocument doc;
  doc.setSweepThreading(DisplaySweeper::Threading::Worker);
  doc.reset(funsho());
  doc.setRequest(ForceResults::forcesRequest(doc.request()));
  ForceResults forces(&doc);
  forces.setThreading(ForceResults::Threading::GuiThread);
  forces.setEnabled(true);
  REQUIRE(forces.state() == ForceResults::State::Ok);
  const k::ForceSweep first = *forces.cycleForces();
  QSignalSpy spy(&forces, &ForceResults::changed);

  REQUIRE_FALSE(doc.edit(longerCrank(doc, 0.5), "crank", MergeKey{ContinuousEdit::DragPoint, 1, 0}));
  REQUIRE(doc.sweepPending());
  // A cycle solved now would pair the new lengths with the last sweep: it waits.
  CHECK(forces.cyclePending());
  CHECK(sameForces(*forces.cycleForces(), first));
  REQUIRE(forces.poseForces() != nullptr);
  REQUIRE(spy.count() == 1);
  CHECK_FALSE(spy.front().front().toBool());

  forces.waitForCycle();
  CHECK_FALSE(forces.cyclePending());
  CHECK(spy.back().front().toBool());
  CHECK(forces.cycleSweep()->inputAngle == doc.sweep().inputAngle);
  CHECK(forces.cycleSweep()->acceleration == doc.sweep().acceleration);
  MechanismDocument inGui;
  inGui.reset(doc.design());
  inGui.setRequest(ForceResults::forcesRequest(inGui.request()));
  ForceResults check(&inGui);
  check.setThreading(ForceResults::Threading::GuiThread);
  check.setEnabled(true);
  CHECK(sameForces(*forces.cycleForces(), *check.cycleForces()));
  CHECK_FALSE(sameForces(*forces.cycleForces(), first));
}
