// Springs among the loads (mass_properties.h): the inverse dynamics against Hooke's law at every
// pose, the frame's share, virtual work with springs, and spring balancing (spring_balance.h):
// the textbook zero-length spring that cancels a weighted crank exactly, and on the funsho
// four-bar an optimum that perturbing k or the free length makes worse.

#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/spring_balance.h"
#include "kinematics/dynamics/spring_search.h"
#include "kinematics/dynamics/virtual_work.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <cmath>
#include <numbers>

using namespace linkwright::kinematics;

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

// The thesis four-bar (mm) with a ground point S at (0, h) above the crank pivot O2.
Mechanism withAnchor(double h) {
  Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  m.points.push_back({"S", GroundPoint{Eigen::Vector2d(0.0, h)}});
  return m;
}

Spring crankSpring(double k, double freeLength, double preload) {
  return {"s", {"crank", "B"}, {"", "S"}, k, freeLength, preload};
}

}  // namespace

TEST_CASE("a spring's force is Hooke's at every pose, and the frame feels it", "[dynamics][springs]") {
  // Massless links: the crank's torque balances the spring's pull on B alone, and nothing is
  // left on the frame (the pull on S and the pivots' reactions cancel).
  const Mechanism m = withAnchor(40.0);
  LinkageDynamics d;
  d.loads.springs = {crankSpring(2000.0, 15.0, 3.0)};
  const auto s = sweep(m, {0.0, kTurn, 73, 2.0, 0.0}).value();
  const auto f = sweepForces(m, d, s).value();
  for (std::size_t j = 0; j < s.size(); ++j) {
    REQUIRE(f.ok(j));
    const Eigen::Vector2d b = 1e-3 * s.position[2][j], anchor(0.0, 0.040);
    const double tension = 2000.0 * ((anchor - b).norm() - 0.015) + 3.0;
    const Eigen::Vector2d pull = tension * (anchor - b).normalized();
    CHECK(f.driveTorque[j] == Approx(-cross(b, pull)).margin(1e-12 * tension));
    CHECK(f.shakingForce[j].norm() <= 1e-12 * tension);
    CHECK(std::abs(f.shakingMoment[j]) <= 1e-12 * tension);
  }
}

TEST_CASE("virtual work with springs, masses and gravity gives the Newton–Euler torque", "[dynamics][springs]") {
  const auto e = findExample("funsho-fourbar").value();
  Mechanism m = e.mechanism;
  m.points.push_back({"S", GroundPoint{Eigen::Vector2d(5.0, 30.0)}});
  LinkageDynamics d = e.dynamics;
  d.loads.gravity = standardGravity();
  d.loads.springs = {{"a", {"coupler", "C"}, {"", "S"}, 500.0, 12.0, -2.0},
                     {"b", {"crank", "B"}, {"rocker", "C"}, 80.0, 30.0, 0.0}};
  for (const double omega : {e.omega, 0.0}) {
    const auto s = sweep(m, {0.0, kTurn, 181, omega, 3.0}).value();
    const auto f = sweepForces(m, d, s).value();
    const auto& t = f.virtualWorkTorque;
    double peak = 0.0, worst = 0.0;
    for (std::size_t j = 0; j < s.size(); ++j) {
      peak = std::max(peak, std::abs(f.driveTorque[j]));
      worst = std::max(worst, std::abs(t[j] - f.driveTorque[j]));
    }
    CHECK(peak > 0.0);
    CHECK(worst <= 1e-9 * peak);
  }
}

TEST_CASE("a zero-length spring from above the pivot cancels a weighted crank exactly", "[dynamics][springs]") {
  // Mass m at the crank's tip (r = 25 mm) under gravity: T0 = m g r cos θ. A spring from B to S
  // at height h has ½ k L² = ½ k (r² + h²) − k r h sin θ, so with k = m g/h and no free length
  // the potential is constant and the crank needs no torque at all (Norton, ch. 12 and the
  // classic gravity-balanced arm).
  const double mass = 2.0, h = 40.0;
  const Mechanism m = withAnchor(h);
  LinkageDynamics d;
  d.links = {{"crank", mass, LinkFramePoint{25.0, 0.0}, 0.0}};
  d.loads.gravity = standardGravity();
  const SweepSpec turn{0.0, kTurn, 361, 0.5, 0.0};
  const auto b = balanceBySpring(m, d, turn, {"crank", "B"}, {"", "S"});
  REQUIRE(b.ok());
  CHECK(b->spring.stiffness == Approx(mass * kStandardGravity / 0.040).epsilon(1e-6));
  CHECK(b->spring.freeLength == Approx(0.0).margin(1e-6));
  CHECK(b->spring.preload == Approx(0.0).margin(1e-6 * mass * kStandardGravity));
  CHECK(b->rmsBefore == Approx(mass * kStandardGravity * 0.025 / std::sqrt(2.0)).epsilon(1e-4));
  CHECK(b->rmsAfter <= 1e-6 * b->rmsBefore);
}

TEST_CASE("spring balancing finds the least RMS torque, and the balanced design's forces agree",
          "[dynamics][springs]") {
  const auto e = findExample("funsho-fourbar").value();
  Mechanism m = e.mechanism;
  m.points.push_back({"S", GroundPoint{Eigen::Vector2d(-10.0, 25.0)}});
  LinkageDynamics d = e.dynamics;
  d.loads.gravity = standardGravity();
  d.loads.torques = {{"rocker", -0.3}};  // a load the spring can take off the motor
  const SweepSpec turn{0.0, kTurn, 361, 20.0, 0.0};
  const auto b = balanceBySpring(m, d, turn, {"rocker", "C"}, {"", "S"});
  REQUIRE(b.ok());
  CHECK(b->rmsAfter < b->rmsBefore);
  // The torque the balanced design's inverse dynamics gives is the one predicted.
  const auto s = sweep(m, turn).value();
  const auto f = sweepForces(m, b->balanced, s).value();
  for (std::size_t j = 0; j < s.size(); ++j)
    CHECK(f.driveTorque[j] == Approx(b->torqueAfter[j]).margin(1e-9 * b->rmsBefore));
  // A minimum: nudging the stiffness or the free length either way raises the RMS.
  const auto rmsWith = [&](const Spring& spring) {
    LinkageDynamics nudged = d;
    nudged.loads.springs = {spring};
    const auto g = sweepForces(m, nudged, s).value();
    return rmsOverTurn(b->angle, g.driveTorque);
  };
  CHECK(rmsWith(b->spring) == Approx(b->rmsAfter).epsilon(1e-9));
  for (const double factor : {0.99, 1.01}) {
    Spring k = b->spring, length = b->spring;
    k.stiffness *= factor;
    length.freeLength = b->spring.freeLength * factor + (b->spring.freeLength == 0.0 ? 0.1 * (factor - 1.0) : 0.0);
    length.preload = b->spring.preload * factor;
    CHECK(rmsWith(k) > b->rmsAfter);
    CHECK(rmsWith(length) > b->rmsAfter);
  }
}

TEST_CASE("springs are refused with the field named", "[dynamics][springs][errors]") {
  const Mechanism m = withAnchor(40.0);
  const auto refused = [&](const Spring& s) {
    LinkageDynamics d;
    d.loads.springs = {s};
    const auto e = checkDynamics(m, d);
    REQUIRE(e.has_value());
    return *e;
  };
  CHECK(refused(crankSpring(-1.0, 0.0, 0.0)).message ==
        "loads.springs[0].stiffness must be between 0 and 1e15 N/m (got -1)");
  CHECK(refused(crankSpring(1.0, -2.0, 0.0)).field == "loads.springs[0].freeLength");
  CHECK(refused(crankSpring(1.0, 0.0, std::nan(""))).field == "loads.springs[0].preload");
  CHECK(refused({"s", {"crank", "C"}, {"", "S"}, 1.0, 0.0, 0.0}).message ==
        "loads.springs[0].first.point must lie on the body of link crank (got \"C\")");
  CHECK(refused({"s", {"crank", "B"}, {"", "C"}, 1.0, 0.0, 0.0}).message ==
        "loads.springs[0].second.point must be a ground point for an end on the frame (got \"C\")");
  // No spring from the rocker's pin to O4 can do anything: its length never changes.
  LinkageDynamics masses;
  masses.links = {{"crank", 1.0, std::nullopt, std::nullopt}};
  masses.loads.gravity = standardGravity();
  const auto none = balanceBySpring(m, masses, {0.0, kTurn, 73, 1.0, 0.0}, {"rocker", "C"}, {"", "O4"});
  REQUIRE_FALSE(none.ok());
  CHECK(none.error().field == "spring");
}

TEST_CASE("a searched spring's ends cancel a weighted crank, the search needing no ends given",
          "[dynamics][springs][search]") {
  const double mass = 2.0;
  const Mechanism m = withAnchor(40.0);
  LinkageDynamics d;
  d.links = {{"crank", mass, LinkFramePoint{25.0, 0.0}, 0.0}};
  d.loads.gravity = standardGravity();
  const auto found = searchSpringBalance(m, d, {0.0, kTurn, 361, 0.5, 0.0}, "crank");
  REQUIRE(found.ok());
  CHECK(found->balance.rmsAfter <= 1e-6 * found->balance.rmsBefore);
  REQUIRE(found->mechanism.points.size() == m.points.size() + 2);
  CHECK(found->mechanism.points[m.points.size()].name == "spring_link");
  CHECK(found->mechanism.points.back().name == "spring_frame");
}

TEST_CASE("a searched spring beats given ends, and moving either end any way raises the RMS",
          "[dynamics][springs][search]") {
  const auto e = findExample("funsho-fourbar").value();
  LinkageDynamics d = e.dynamics;
  d.loads.gravity = standardGravity();
  d.loads.torques = {{"rocker", -0.3}};
  const SweepSpec turn{0.0, kTurn, 361, 20.0, 0.0};
  const auto found = searchSpringBalance(e.mechanism, d, turn, "rocker", "lift");
  REQUIRE(found.ok());
  const SpringBalance& b = found->balance;
  CHECK(b.spring.name == "lift");
  CHECK(b.rmsAfter < 0.5 * b.rmsBefore);

  // Better than the ends the test above gives by hand (C to a frame point S).
  Mechanism given = e.mechanism;
  given.points.push_back({"S", GroundPoint{Eigen::Vector2d(-10.0, 25.0)}});
  CHECK(b.rmsAfter <= balanceBySpring(given, d, turn, {"rocker", "C"}, {"", "S"})->rmsAfter);

  // The balanced design's own inverse dynamics gives the torque predicted.
  const auto s = sweep(found->mechanism, turn).value();
  const auto f = sweepForces(found->mechanism, b.balanced, s).value();
  for (std::size_t j = 0; j < s.size(); ++j)
    CHECK(f.driveTorque[j] == Approx(b.torqueAfter[j]).margin(1e-9 * b.rmsBefore));

  // A minimum over the placement: each end moved 0.5 mm along either axis, the spring sized
  // again for its new ends, gives a higher RMS.
  const std::size_t onLink = e.mechanism.points.size(), onFrame = onLink + 1;
  int compared = 0;
  for (std::size_t axis = 0; axis < 4; ++axis)
    for (const double sign : {1.0, -1.0}) {
      CAPTURE(axis, sign);
      Mechanism moved = found->mechanism;
      if (axis < 2) {
        auto& a = std::get<AttachedPoint>(moved.points[onLink].definition);
        (axis == 0 ? a.along : a.across) += 0.5 * sign;
      } else {
        auto& g = std::get<GroundPoint>(moved.points[onFrame].definition);
        g.position[static_cast<Eigen::Index>(axis - 2)] += 0.5 * sign;
      }
      const auto other = balanceBySpring(moved, d, turn, b.spring.first, b.spring.second, "lift");
      if (!other) continue;
      CHECK(other->rmsAfter > b.rmsAfter);
      ++compared;
    }
  CHECK(compared == 8);
}

TEST_CASE("a spring search names the link it cannot use", "[dynamics][springs][search][errors]") {
  const auto e = findExample("funsho-fourbar").value();
  const auto r = searchSpringBalance(e.mechanism, e.dynamics, {0.0, kTurn, 361, 20.0, 0.0}, "boom");
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().field == "link");
  CHECK(r.error().message == "the spring's link must be one of the linkage's (crank, coupler, rocker); got \"boom\"");
}
