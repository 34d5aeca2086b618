// Forces over whole sweeps (force_sweep.h): the power balance at every sample of every kind of
// linkage, virtual work over a turn, and how samples that are not Ok are reported.

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/solve/sweep.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"
#include "tests/kinematics/dynamics/power_balance.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::poseAt;

TEST_CASE("sweepForces: power balance at every sample of every kind of linkage and driver", "[dynamics]") {
  // Drive power (T·ω2, f·q̇ or F·v) + loads' power + gravity's power = dE/dt, to 1e-9 of the
  // sum of the terms' sizes (the figure; the residual is round-off, about 1e-13 here).
  auto cases = linkwright::test::dynamicsCases();
  for (auto& c : linkwright::test::drivenDynamicsCases()) cases.push_back(std::move(c));
  for (const auto& c : cases) {
    CAPTURE(c.name);
    const auto s = sweep(c.mechanism, c.spec);
    REQUIRE(s.ok());
    const auto forces = sweepForces(c.mechanism, c.dynamics, *s);
    INFO((forces.ok() ? std::string() : forces.error().message));
    REQUIRE(forces.ok());
    REQUIRE(forces->size() == c.spec.samples);
    double worst = 0.0;
    for (std::size_t j = 0; j < s->size(); ++j) {
      REQUIRE(s->ok(j));
      REQUIRE(forces->ok(j));
      const Pose pose = poseAt(c.mechanism, *s, j);
      const double drive = linkwright::test::drivePower(c.mechanism, pose, forces->at(j));
      const auto b = linkwright::test::powerBalance(c.mechanism, c.dynamics, pose, drive);
      if (b.scale == 0.0) {  // at rest with no load moving: every term is exactly zero
        CHECK(b.residual() == 0.0);
        continue;
      }
      worst = std::max(worst, std::abs(b.residual()) / b.scale);
    }
    CAPTURE(worst);
    CHECK(worst <= 1e-9);
  }
}

TEST_CASE("sweepForces: virtual work over a turn, massless links", "[dynamics]") {
  const double omega = 7.0;
  SECTION("a load torque on the rocker: T2 = −TL·ω4/ω2") {
    const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
    LinkageDynamics d;
    d.loads.torques = {{"rocker", -4.0}};
    const auto s = sweep(m, {0.0, 2.0 * kPi, 73, omega, 0.0});
    const auto f = sweepForces(m, d, s.value());
    REQUIRE(f.ok());
    for (std::size_t j = 0; j < s->size(); ++j) {
      const double expected = 4.0 * s->linkOmega[fourbar::kRocker.index][j] / omega;
      CHECK(f->driveTorque[j] == Approx(expected).epsilon(1e-12).margin(1e-12));
    }
  }
  SECTION("a force on the slider: T = −F·v/ω2") {
    const Mechanism m = makeSliderCrank(kLs3Engine).value();
    LinkageDynamics d;
    const Eigen::Vector2d force(-2500.0, 0.0);
    d.loads.forces = {{"", "C", 0, force}};
    const auto s = sweep(m, {0.0, 2.0 * kPi, 73, omega, 0.0});
    const auto f = sweepForces(m, d, s.value());
    REQUIRE(f.ok());
    for (std::size_t j = 0; j < s->size(); ++j) {
      const double expected = -force.dot(1e-3 * s->velocity[slidercrank::kC.index][j]) / omega;
      CHECK(f->driveTorque[j] == Approx(expected).epsilon(1e-12).margin(1e-9));
    }
  }
}

TEST_CASE("sweepForces: samples that are not Ok keep their status and hold zeros", "[dynamics]") {
  // Crank 10, coupler 35, rocker 15, frame 30: at 0° B and O4 are 20 apart = coupler − rocker,
  // a toggle (Singular); everywhere else it assembles with rates.
  const Mechanism m = makeFourBar({30.0, 10.0, 35.0, 15.0}, Branch::Open).value();
  LinkageDynamics d;
  d.links = {{"coupler", 0.5, std::nullopt, std::nullopt}};
  const auto s = sweep(m, {0.0, degToRad(180.0), 7, 10.0, 0.0});
  REQUIRE(s.ok());
  REQUIRE(s->report[0].status == PoseStatus::Singular);
  const auto f = sweepForces(m, d, *s);
  REQUIRE(f.ok());
  CHECK(f->status[0] == PoseStatus::Singular);
  CHECK(f->driveTorque[0] == 0.0);
  for (std::size_t j = 1; j < s->size(); ++j) {
    CAPTURE(j);
    CHECK(f->status[j] == s->report[j].status);
    if (!s->ok(j)) CHECK(f->revolute[0][j] == Eigen::Vector2d::Zero());
    else CHECK(f->revolute[0][j] != Eigen::Vector2d::Zero());
  }
  CHECK(f->at(0).driveTorque == 0.0);
}

TEST_CASE("sweepForces: a sweep without accelerations is refused", "[dynamics]") {
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  const auto s = sweep(m, {0.0, 1.0, 3, 1.0, 0.0}, SolveRequest{true, false});
  REQUIRE(s.ok());
  const auto f = sweepForces(m, {}, *s);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().field == "request.accelerations");
}
