// Inverse dynamics at one pose (inverse_dynamics.h): statics against virtual work, the frame
// reactions against momentum, units, a toggle position reported as Singular, and the
// link-by-link solve against the LU of the whole system.

#include "kinematics/dynamics/inverse_dynamics.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>

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
  REQUIRE(solver.value().solvesLinkByLink());
  CHECK(solver.value().solveInto(pose, out) == PoseStatus::Singular);
  CHECK(solver.value().lastMethod() == InverseDynamics::Method::Lu);  // the LU decided it
  CHECK(out.driveTorque == 0.0);
  CHECK(solver.value().solveByLuInto(pose, out) == PoseStatus::Singular);
  // Moved off the toggle the same system solves, link by link.
  pose.position[fourbar::kB.index] = {31.0, 55.0};
  CHECK(solver.value().solveInto(pose, out) == PoseStatus::Ok);
  CHECK(solver.value().lastMethod() == InverseDynamics::Method::LinkByLink);
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

namespace {

// The largest difference between two solutions, each quantity against the largest of its kind
// in `a` (forces in N, moments in N·m): 0 when they agree exactly.
double worstDifference(const PoseForces& a, const PoseForces& b) {
  double force = 0.0;
  double moment = 0.0;
  for (const Eigen::Vector2d& f : a.revolute) force = std::max(force, f.norm());
  for (const double n : a.normal) force = std::max(force, std::abs(n));
  for (const double m : a.moment) moment = std::max(moment, std::abs(m));
  force = std::max({force, std::abs(a.driveAlong), a.driveForce.norm(), a.shakingForce.norm()});
  moment = std::max({moment, std::abs(a.driveTorque), std::abs(a.shakingMoment), a.jointTorque.cwiseAbs().maxCoeff()});
  double worst = 0.0;
  const auto differ = [&](double x, double y, double scale) {
    const double d = std::abs(x - y);
    worst = std::max(worst, d == 0.0 ? 0.0 : d / scale);
  };
  for (std::size_t j = 0; j < a.revolute.size(); ++j) {
    differ(a.revolute[j].x(), b.revolute[j].x(), force);
    differ(a.revolute[j].y(), b.revolute[j].y(), force);
  }
  for (std::size_t j = 0; j < a.normal.size(); ++j) {
    differ(a.normal[j], b.normal[j], force);
    differ(a.moment[j], b.moment[j], moment);
  }
  differ(a.driveTorque, b.driveTorque, moment);
  differ(a.driveAlong, b.driveAlong, force);
  for (int i = 0; i < 2; ++i) {
    differ(a.driveForce[i], b.driveForce[i], force);
    differ(a.jointTorque[i], b.jointTorque[i], moment);
    differ(a.shakingForce[i], b.shakingForce[i], force);
  }
  differ(a.shakingMoment, b.shakingMoment, moment);
  return worst;
}

// Solves `pose` both ways; they must agree on the status and, where Ok, to 1e-9. Returns the
// way solveInto went.
InverseDynamics::Method compareWithLu(InverseDynamics& solver, const Pose& pose, std::optional<double> input) {
  PoseForces fast;
  PoseForces lu;
  solver.prepare(fast);
  solver.prepare(lu);
  const PoseStatus fastStatus = solver.solveInto(pose, fast, input);
  const InverseDynamics::Method method = solver.lastMethod();
  const PoseStatus luStatus = solver.solveByLuInto(pose, lu, input);
  REQUIRE(fastStatus == luStatus);
  if (fastStatus == PoseStatus::Ok) CHECK(worstDifference(lu, fast) <= 1e-9);
  return method;
}

}  // namespace

TEST_CASE("inverse dynamics: link by link on every dyad chain, the LU on the rest, the same forces", "[dynamics]") {
  // Every kind of linkage and driver over its sweep: linkages made of a crank and dyads with a
  // pin in the middle (RRR, RRP, PRP) or of such dyads driven along a path (the arm, the
  // slider-crank worked from its piston) are solved link by link at every sample; a slide in a
  // dyad's middle (the shaper's RPR), a triad (Stephenson II) and an actuator (the boom's
  // cylinder) take the LU.
  const std::map<std::string, bool> linkByLink{
      {"four-bar", true},        {"slider-crank", true},  {"shaper", false},  {"watt-ii", true},
      {"stephenson-ii", false},  {"prp-yoke", true},      {"seed-arm", true}, {"piston-driven", true},
      {"excavator-boom", false}, {"funsho-fourbar", true}};
  auto cases = linkwright::test::dynamicsCases();
  for (auto& c : linkwright::test::drivenDynamicsCases()) cases.push_back(std::move(c));
  const Example funsho = findExample("funsho-fourbar").value();
  cases.push_back({"funsho-fourbar", funsho.mechanism, funsho.dynamics, {0.0, 2.0 * kPi, 3600, funsho.omega, 0.5}});
  REQUIRE(cases.size() == linkByLink.size());
  for (const auto& c : cases) {
    CAPTURE(c.name);
    auto solver = InverseDynamics::create(c.mechanism, c.dynamics);
    REQUIRE(solver.ok());
    CHECK(solver.value().solvesLinkByLink() == linkByLink.at(c.name));
    const auto s = sweep(c.mechanism, c.spec);
    REQUIRE(s.ok());
    for (std::size_t j = 0; j < s->size(); ++j) {
      REQUIRE(s->ok(j));
      const auto method = compareWithLu(solver.value(), linkwright::test::poseAt(c.mechanism, *s, j), s->inputAngle[j]);
      CHECK((method == InverseDynamics::Method::LinkByLink) == linkByLink.at(c.name));
    }
  }
}

TEST_CASE("inverse dynamics: link by link agrees with the LU on random four-bars and slider-cranks", "[dynamics]") {
  // Random proportions, masses, centres off the link line, inertias, gravity in any direction,
  // a torque on the output and a force on the coupler or the block; ω and α of the crank; 24
  // crank angles each, those that assemble.
  std::mt19937 rng(20261128);
  const auto uniform = [&](double low, double high) { return std::uniform_real_distribution<double>(low, high)(rng); };
  const auto randomMass = [&](const std::string& link, double length) {
    return LinkMass{link, uniform(0.0, 2.0), LinkFramePoint{uniform(-0.2, 1.2) * length, uniform(-0.3, 0.3) * length},
                    uniform(0.0, 1e-3)};
  };
  int compared = 0;
  int linkByLink = 0;
  for (int k = 0; k < 200; ++k) {
    const bool slider = k % 2 == 1;
    CAPTURE(k);
    Mechanism m;
    LinkageDynamics d;
    d.loads.gravity = Eigen::Vector2d(uniform(-10.0, 10.0), uniform(-10.0, 10.0));
    if (slider) {
      // The rod longer than crank + |offset|: it is never square to the guide (the RRP toggle).
      SliderCrankGeometry h{uniform(10.0, 50.0), 0.0, uniform(-20.0, 20.0), uniform(0.0, 1.0) < 0.5};
      h.rod = h.crank * uniform(1.5, 5.0) + std::abs(h.offset);
      m = makeSliderCrank(h, uniform(0.0, 1.0) < 0.5 ? Branch::Open : Branch::Crossed).value();
      d.links = {randomMass("crank", h.crank), randomMass("rod", h.rod)};
      d.sliders = {{"C", 0, uniform(0.0, 3.0), uniform(0.0, 1e-4)}};
      d.loads.forces = {{"", "C", 0, Eigen::Vector2d(uniform(-500.0, 500.0), uniform(-500.0, 500.0))}};
      d.loads.torques = {{"rod", uniform(-2.0, 2.0)}};
    } else {
      const FourBarLengths l{uniform(20.0, 80.0), uniform(5.0, 40.0), uniform(20.0, 90.0), uniform(15.0, 80.0)};
      m = makeFourBar(l, uniform(0.0, 1.0) < 0.5 ? Branch::Open : Branch::Crossed).value();
      d.links = {randomMass("crank", l.crank), randomMass("coupler", l.coupler), randomMass("rocker", l.rocker)};
      d.loads.forces = {{"coupler", "C", 0, Eigen::Vector2d(uniform(-100.0, 100.0), uniform(-100.0, 100.0))}};
      d.loads.torques = {{"rocker", uniform(-5.0, 5.0)}};
    }
    auto solver = InverseDynamics::create(m, d);
    REQUIRE(solver.ok());
    REQUIRE(solver.value().solvesLinkByLink());
    const double omega = uniform(-100.0, 100.0);
    const double alpha = uniform(-1000.0, 1000.0);
    for (int a = 0; a < 24; ++a) {
      const auto pose = solvePose(m, {2.0 * kPi * a / 24.0, omega, alpha});
      if (!pose.ok()) continue;
      ++compared;
      if (compareWithLu(solver.value(), pose.value(), std::nullopt) == InverseDynamics::Method::LinkByLink)
        ++linkByLink;
    }
  }
  CHECK(compared > 2000);
  CHECK(linkByLink == compared);  // none of these poses is within 1e-6 of a toggle
}

TEST_CASE("inverse dynamics: toward a toggle both ways agree, and the LU decides within kChainMargin", "[dynamics]") {
  // The toggle of the Singular test above (coupler B→C straight down onto the rocker O4→C),
  // with B moved sideways by ε: the dyad's sine is that of the angle between C − B and C − O4,
  // about ε / 35 mm.
  const Mechanism m = makeFourBar({30.0, std::sqrt(30.0 * 30.0 + 55.0 * 55.0), 35.0, 20.0}, Branch::Open).value();
  LinkageDynamics d;
  d.links = {{"crank", 0.2, std::nullopt, std::nullopt}, {"coupler", 0.6, LinkFramePoint{17.5, 3.0}, 4e-4}};
  d.loads.torques = {{"rocker", 1.0}};
  auto solver = InverseDynamics::create(m, d);
  REQUIRE(solver.ok());
  Pose pose;
  preparePose(m, pose);
  pose.position[fourbar::kO4.index] = {30.0, 0.0};
  pose.position[fourbar::kC.index] = {30.0, 20.0};
  for (const double epsilon : {0.0, 1e-13, 1e-11, 1e-9, 1e-7, 1e-5, 1e-3, 1e-1, 1.0}) {
    CAPTURE(epsilon);
    pose.position[fourbar::kB.index] = {30.0 + epsilon, 55.0};
    const auto method = compareWithLu(solver.value(), pose, std::nullopt);
    CHECK((method == InverseDynamics::Method::LinkByLink) == (epsilon / 35.0 > kChainMargin));
  }
}
