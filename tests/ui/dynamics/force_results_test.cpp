// ForceResults: solves nothing while disabled; while enabled, its columns are exactly the
// core's sweepForces on the sweep it names, a crank move re-solves the pose forces only, and a
// design without masses or with an unknown length unit says so.
#include "ui/document/force_results.h"

#include "ui/document/mechanism_document.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"

#include <QSignalSpy>

#include <catch2/catch.hpp>

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
    CHECK(forces.cycleSweep() == &doc.sweep());
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
