// Tests kinematics/model/sixbar_newton.h: the Stephenson III driven from the wrong link and
// the Stephenson II, built with free points, assemble over a whole crank turn with every
// distance closed, come back to where they started, keep Newton's work small, have rates
// that match central differences of their positions, count as six-bars with M = 1, and name
// the field of a bad dimension.

#include "kinematics/model/sixbar_newton.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/newton_group.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::checkRate;
using linkwright::test::differentiate;

namespace {

struct Case {
  std::string name;
  Mechanism mechanism;
};

std::vector<Case> cases() {
  const auto three = makeStephensonIIINewton();
  const auto two = makeStephensonIINewton();
  REQUIRE(three.ok());
  REQUIRE(two.ok());
  return {{"Stephenson III", *three}, {"Stephenson II", *two}};
}

// The size Newton's tolerance is relative to: the longest distance or farthest ground pivot.
double size(const Mechanism& m) {
  double s = 0.0;
  for (const DistanceConstraint& c : m.constraints) s = std::max(s, c.length);
  for (const Point& p : m.points)
    if (const auto* g = std::get_if<GroundPoint>(&p.definition)) s = std::max(s, g->position.norm());
  return s;
}

// Solves at crank angles 0°, 1°, … up to `angleDeg` with one pose, as a sweep does, so that the
// free points reach `angleDeg` on the assembly the guesses describe.
void followTo(const Mechanism& m, double angleDeg, const SolveRequest& request, Pose& pose) {
  preparePose(m, pose);
  for (double a = 0.0; a < angleDeg; a += 1.0)
    REQUIRE(solvePoseInto(m, {degToRad(a), 0.0, 0.0}, request, pose).status == PoseStatus::Ok);
}

}  // namespace

TEST_CASE("The Newton six-bars are valid six-bars with one degree of freedom", "[sixbar_newton]") {
  const auto three = makeStephensonIIINewton();
  REQUIRE(three.ok());
  CHECK_FALSE(checkMechanism(*three).has_value());
  CHECK(three->points[stephenson3::kE.index].name == "E");
  CHECK(three->links[stephenson3::kRocker6.index].name == "rocker6");
  CHECK(three->links[stephenson3::kTernary.index].first == stephenson3::kC);
  // Ground, crank, coupler, the ternary plate (its three sides form one triangle), two rockers:
  // N = 6; pins O2, B, C, D, E, O4, O6: jp = 7; M = 3·5 − 2·7 = 1.
  CHECK(mobility(*three) == MobilityReport{6, 7, 0, 1});

  const auto two = makeStephensonIINewton();
  REQUIRE(two.ok());
  CHECK_FALSE(checkMechanism(*two).has_value());
  CHECK(two->points[stephenson2::kJ6.index].name == "J6");
  CHECK(two->links[stephenson2::kLink6.index].name == "link6");
  // Ground, crank, two ternaries (one triangle each), link5, link6: N = 6, jp = 7, M = 1.
  CHECK(mobility(*two) == MobilityReport{6, 7, 0, 1});
}

TEST_CASE("The Newton six-bars assemble over a whole turn, every distance closed", "[sixbar_newton]") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const Mechanism& m = c.mechanism;
    const SweepSpec spec{0.0, 2.0 * kPi, 361, 2.0 * kPi, 0.0};
    const auto r = sweep(m, spec);
    REQUIRE(r.ok());
    CHECK(r->notAssembled.empty());
    CHECK(r->singularAngles.empty());
    CHECK(linkwright::test::firstNonFinite(*r).empty());
    const double scale = size(m);
    double worstMisfit = 0.0;
    int mostIterations = 0;
    for (std::size_t j = 0; j < r->size(); ++j) {
      CAPTURE(j);
      REQUIRE(r->ok(j));
      for (const DistanceConstraint& d : m.constraints) {
        const double misfit = (r->position[d.first.index][j] - r->position[d.second.index][j]).norm() - d.length;
        worstMisfit = std::max(worstMisfit, std::abs(misfit));
      }
      if (j > 0) mostIterations = std::max(mostIterations, r->report[j].iterations);
    }
    // Newton's default tolerance is 1e-12 of the size; the misfit |pa − pb| − L equals the
    // residual it tests to first order.
    CAPTURE(worstMisfit, mostIterations);
    CHECK(worstMisfit <= 1e-10 * scale);
    // Warm-started 1° back, the crank tip moves 25 mm × 0.0175 = 0.44 mm, 0.3% of the size;
    // quadratic convergence (error ≈ e²/σ with σ ≥ 0.35) reaches 1e-12 in three steps.
    CHECK(mostIterations <= 4);
    // After a full turn the linkage is back where it started: it stayed on one assembly.
    for (std::size_t i = 0; i < m.points.size(); ++i)
      CHECK((r->position[i][360] - r->position[i][0]).norm() <= 1e-9 * scale);
    // The guesses are the assembly at 0°, rounded to 1 mm.
    for (std::size_t i = 0; i < m.points.size(); ++i)
      if (const auto* f = std::get_if<FreePoint>(&m.points[i].definition))
        CHECK((r->position[i][0] - f->guess).norm() <= std::sqrt(0.5));
  }
}

TEST_CASE("The Newton six-bars' rates match central differences of their positions", "[sixbar_newton]") {
  const double degrees = GENERATE(30.0, 100.0, 200.0, 300.0);
  CAPTURE(degrees);
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const Mechanism& m = c.mechanism;
    // The tightest tolerance Newton takes: position noise ≤ 1e-14·size/σ ≈ 5e-12 mm (σ ≥ 0.35),
    // so 1e-11 mm bounds it, and 1e-12 rad the link angles (links ≥ 25 mm).
    SolveRequest precise;
    precise.newton.tolerance = 1e-14;
    SolveRequest positions = precise;
    positions.velocities = positions.accelerations = false;
    const double omega = 10.0, alpha = 25.0, h = 1e-4;
    Pose pose;
    followTo(m, degrees, positions, pose);
    const double theta0 = degToRad(degrees);
    REQUIRE(solvePoseInto(m, {theta0, omega, alpha}, precise, pose).status == PoseStatus::Ok);
    const Pose exact = pose;
    std::array<Pose, 5> stencil;
    for (int k = -2; k <= 2; ++k) {
      const double t = k * h;
      REQUIRE(solvePoseInto(m, {theta0 + omega * t + 0.5 * alpha * t * t, 0.0, 0.0}, positions, pose).status ==
              PoseStatus::Ok);
      stencil[static_cast<std::size_t>(k + 2)] = pose;
    }
    for (std::size_t i = 0; i < m.points.size(); ++i)
      for (int axis = 0; axis < 2; ++axis) {
        std::array<double, 5> q{};
        for (std::size_t k = 0; k < 5; ++k) q[k] = stencil[k].position[i][axis];
        const auto d = differentiate(q, h, 1e-11);
        const std::string what = m.points[i].name + (axis == 0 ? ".x" : ".y");
        checkRate(exact.velocity[i][axis], d[0], what + " velocity");
        checkRate(exact.acceleration[i][axis], d[1], what + " acceleration");
      }
    for (std::size_t l = 0; l < m.links.size(); ++l) {
      std::array<double, 5> q{};
      const double centre = stencil[2].linkAngle[l];
      for (std::size_t k = 0; k < 5; ++k) q[k] = centre + angleDifference(stencil[k].linkAngle[l], centre);
      const auto d = differentiate(q, h, 1e-12);
      checkRate(exact.linkOmega[l], d[0], m.links[l].name + " omega");
      checkRate(exact.linkAlpha[l], d[1], m.links[l].name + " alpha");
    }
  }
}

TEST_CASE("A Newton six-bar that cannot close says so, naming its free points", "[sixbar_newton][errors]") {
  StephensonIIIGeometry g = kStephensonIIINewton;
  g.de = 200.0;  // longer than the ternary's other sides together (80 + 90): no triangle
  const auto m = makeStephensonIIINewton(g);
  REQUIRE(m.ok());
  const auto pose = solvePose(*m, {0.0, 1.0, 0.0});
  REQUIRE_FALSE(pose.ok());
  CHECK(pose.error().code == ErrorCode::NotAssemblable);
  CHECK(pose.error().field == "C");
  CAPTURE(pose.error().message);
  CHECK(pose.error().message.find(
            "C, D, E cannot be assembled at crank angle 0°: Newton did not converge (residual ") == 0);
  CHECK(pose.error().message.find("); the linkage probably cannot close here") != std::string::npos);
  const auto r = sweep(*m, {0.0, 2.0 * kPi, 37, 1.0, 0.0});
  REQUIRE(r.ok());
  REQUIRE(r->notAssembled.size() == 1);
  CHECK(r->notAssembled[0] == AngleRange{0.0, 2.0 * kPi});
  for (std::size_t j = 0; j < r->size(); ++j) CHECK(r->report[j].failure == AssemblyFailure::NoConvergence);
}

TEST_CASE("The Newton six-bar builders name a bad dimension", "[sixbar_newton][errors]") {
  StephensonIIIGeometry three = kStephensonIIINewton;
  three.cd = -5.0;
  auto e = makeStephensonIIINewton(three);
  REQUIRE_FALSE(e.ok());
  CHECK(e.error().field == "cd");
  CHECK(e.error().message == "cd length must be positive and finite (got -5)");
  three = kStephensonIIINewton;
  three.guessE.x() = std::numeric_limits<double>::infinity();
  CHECK(makeStephensonIIINewton(three).error().field == "guessE.x");

  StephensonIIGeometry two = kStephensonIINewton;
  two.link5 = 0.0;
  CHECK(makeStephensonIINewton(two).error().field == "link5");
  two = kStephensonIINewton;
  two.j5.y() = std::numeric_limits<double>::quiet_NaN();
  CHECK(makeStephensonIINewton(two).error().message == "j5.y must be finite (got undefined)");
}
