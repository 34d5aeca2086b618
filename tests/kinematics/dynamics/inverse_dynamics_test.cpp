// Inverse dynamics at one pose (inverse_dynamics.h): statics against virtual work, the frame
// reactions against momentum, units, and a toggle position reported as Singular.

#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("inverse dynamics: massless four-bar with a load torque matches virtual work", "[dynamics]") {
  // Statics: T2·ω2 + TL·ω4 = 0, so T2 = −TL·ω4/ω2 (the velocity ratio from the kinematics).
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  LinkageDynamics d;
  d.loads.torques = {{"rocker", 3.0}};
  const double angleDeg = GENERATE(0.0, 37.0, 90.0, 181.0, 275.0);
  CAPTURE(angleDeg);
  const Pose pose = solvePose(m, {degToRad(angleDeg), 2.0, 0.0}).value();
  const auto forces = forcesAtPose(m, d, pose);
  REQUIRE(forces.ok());
  const double expected = -3.0 * pose.linkOmega[fourbar::kRocker.index] / 2.0;
  CHECK(forces->driveTorque == Approx(expected).epsilon(1e-12).margin(1e-12));
  // The coupler is a two-force member: its pin forces lie along B→C.
  const Eigen::Vector2d bc = pose.position[fourbar::kC.index] - pose.position[fourbar::kB.index];
  CHECK(std::abs(cross(bc.normalized(), forces->revolute[2])) <= 1e-12 * forces->revolute[2].norm());
}

TEST_CASE("inverse dynamics: massless slider-crank with a force on the piston matches virtual work", "[dynamics]") {
  // T·ω2 + F·vC = 0, so T = −F·vC/ω2 (vC in m/s).
  const Mechanism m = makeSliderCrank(kLs3Engine).value();
  LinkageDynamics d;
  d.loads.forces = {{"", "C", 0, Eigen::Vector2d(-1000.0, 0.0)}};
  const double angleDeg = GENERATE(10.0, 60.0, 135.0, 250.0, 330.0);
  CAPTURE(angleDeg);
  const double omega = 50.0;
  const Pose pose = solvePose(m, {degToRad(angleDeg), omega, 0.0}).value();
  const auto forces = forcesAtPose(m, d, pose);
  REQUIRE(forces.ok());
  const double vC = 1e-3 * pose.velocity[slidercrank::kC.index].x();
  CHECK(forces->driveTorque == Approx(1000.0 * vC / omega).epsilon(1e-12).margin(1e-12));
  // The piston's block is pushed against its guide by the rod's sideways component.
  CHECK(forces->moment[0] == Approx(0.0).margin(1e-9));
}

TEST_CASE("inverse dynamics: the frame reactions are minus the rate of change of momentum", "[dynamics]") {
  // With no gravity and no loads: shaking force = −Σ m a_G, shaking moment about O2 =
  // −Σ (I α + (G − O2)×m a_G). Checked on a four-bar (pins only) and a shaper (ground guide).
  for (linkwright::test::DynamicsCase c : linkwright::test::dynamicsCases()) {
    if (c.name != "four-bar" && c.name != "shaper") continue;
    CAPTURE(c.name);
    c.dynamics.loads = {};
    const Pose pose = solvePose(c.mechanism, {0.7, c.spec.omega, c.spec.alpha}).value();
    const auto forces = forcesAtPose(c.mechanism, c.dynamics, pose);
    REQUIRE(forces.ok());
    const double s = 1e-3;
    Eigen::Vector2d momentumRate = Eigen::Vector2d::Zero();
    double angularRate = 0.0;
    double scale = 0.0;
    for (const LinkMass& l : c.dynamics.links) {
      const Link& link = c.mechanism.links[c.mechanism.findLink(l.link)->index];
      const std::size_t k = c.mechanism.findLink(l.link)->index;
      const Eigen::Vector2d a = s * pose.position[link.first.index];
      const Eigen::Vector2d e = s * pose.position[link.second.index] - a;
      const LinkFramePoint cp = l.centre.value_or(LinkFramePoint{0.5 * e.norm() / s, 0.0});
      const Eigen::Vector2d r = s * (cp.along * e.normalized() + cp.across * perp(e.normalized()));
      const double w = pose.linkOmega[k];
      const Eigen::Vector2d aG = s * pose.acceleration[link.first.index] + pose.linkAlpha[k] * perp(r) - w * w * r;
      const double inertia = l.inertia.value_or(l.mass * e.squaredNorm() / 12.0);
      momentumRate += l.mass * aG;
      angularRate += inertia * pose.linkAlpha[k] + cross(a + r, l.mass * aG);
      scale += l.mass * aG.norm() * (1.0 + (a + r).norm());
    }
    for (const SliderMass& sm : c.dynamics.sliders) {
      const PointId point = *c.mechanism.findPoint(sm.point);
      const auto* rpr = std::get_if<RprPoint>(&c.mechanism.points[point.index].definition);
      const PointId pin = rpr ? rpr->through : point;
      const Eigen::Vector2d aG = s * pose.acceleration[pin.index];
      double alpha = 0.0;
      if (rpr) alpha = pose.linkAlpha[shaper::kRocker.index];
      momentumRate += sm.mass * aG;
      angularRate += sm.inertia * alpha + cross(s * pose.position[pin.index], sm.mass * aG);
      scale += sm.mass * aG.norm() * (1.0 + s * pose.position[pin.index].norm());
    }
    CHECK((forces->shakingForce + momentumRate).norm() <= 1e-12 * scale);
    CHECK(std::abs(forces->shakingMoment + angularRate) <= 1e-12 * scale);
  }
}

TEST_CASE("inverse dynamics: the same linkage in metres and in millimetres gives the same forces", "[dynamics]") {
  LinkageDynamics d;
  d.links = {{"crank", 0.2, std::nullopt, std::nullopt},
             {"coupler", 0.6, LinkFramePoint{17.5, 2.0}, 4e-4},
             {"rocker", 0.4, std::nullopt, 8e-5}};
  d.loads.gravity = standardGravity();
  const Mechanism mm = makeFourBar({30.0, 10.0, 35.0, 20.0}, Branch::Open, "mm").value();
  const Mechanism metres = makeFourBar({0.03, 0.01, 0.035, 0.02}, Branch::Open, "m").value();
  LinkageDynamics dm = d;
  dm.links[1].centre = LinkFramePoint{0.0175, 0.002};
  const auto a = forcesAtPose(mm, d, solvePose(mm, {1.0, 100.0, 0.0}).value());
  const auto b = forcesAtPose(metres, dm, solvePose(metres, {1.0, 100.0, 0.0}).value());
  REQUIRE(a.ok());
  REQUIRE(b.ok());
  CHECK(a->driveTorque == Approx(b->driveTorque).epsilon(1e-12));
  for (std::size_t j = 0; j < a->revolute.size(); ++j)
    CHECK((a->revolute[j] - b->revolute[j]).norm() <= 1e-12 * a->revolute[j].norm());
}

TEST_CASE("inverse dynamics: a four-bar at a toggle position is Singular, not numbers", "[dynamics]") {
  // Rocker O4→C straight up and coupler B→C straight down onto it: collinear, so no force
  // along the coupler can turn the rocker. Built by hand so the positions are exact.
  const Mechanism m = makeFourBar({30.0, std::sqrt(30.0 * 30.0 + 55.0 * 55.0), 35.0, 20.0}, Branch::Open).value();
  Pose pose;
  preparePose(m, pose);
  pose.position[fourbar::kO2.index] = {0.0, 0.0};
  pose.position[fourbar::kO4.index] = {30.0, 0.0};
  pose.position[fourbar::kB.index] = {30.0, 55.0};
  pose.position[fourbar::kC.index] = {30.0, 20.0};
  LinkageDynamics d;
  d.loads.torques = {{"rocker", 1.0}};
  const auto forces = forcesAtPose(m, d, pose);
  REQUIRE_FALSE(forces.ok());
  CHECK(forces.error().code == ErrorCode::Singular);
  auto solver = InverseDynamics::create(m, d);
  REQUIRE(solver.ok());
  PoseForces out;
  solver.value().prepare(out);
  CHECK(solver.value().solveInto(pose, out) == PoseStatus::Singular);
  CHECK(out.driveTorque == 0.0);
  // Moved off the toggle the same system solves.
  pose.position[fourbar::kB.index] = {31.0, 55.0};
  CHECK(solver.value().solveInto(pose, out) == PoseStatus::Ok);
}

TEST_CASE("inverse dynamics: errors name the field", "[dynamics]") {
  const Mechanism m = makeFourBar({30.0, 10.0, 35.0, 20.0}, Branch::Open, "furlong").value();
  LinkageDynamics d;
  d.links = {{"crank", 0.2, std::nullopt, std::nullopt}};
  const auto unknownUnit = InverseDynamics::create(m, d);
  REQUIRE_FALSE(unknownUnit.ok());
  CHECK(unknownUnit.error().field == "lengthUnit");
  CHECK(unknownUnit.error().message ==
        "lengthUnit must be m, cm, mm, in or ft for forces, which need lengths in metres (got \"furlong\")");
  Mechanism mm = m;
  mm.lengthUnit = "mm";
  d.links[0].mass = -1.0;
  const auto negative = InverseDynamics::create(mm, d);
  REQUIRE_FALSE(negative.ok());
  CHECK(negative.error().message == "links[0].mass must be between 0 and 1e9 kg (got -1)");
}
