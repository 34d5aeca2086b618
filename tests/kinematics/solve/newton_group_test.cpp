// Tests kinematics/solve/newton_group.h through the pose solver and the sweep: Newton on free
// points against the closed-form dyads on the same linkages (constraint_form.h's
// withNewtonPoints), its iteration counts when warm-started along a sweep, the reports when
// a pose cannot close or is singular, the settings check, and the structure errors
// checkMechanism gives for free points and distance constraints.

#include "kinematics/solve/newton_group.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/constraint_form.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::kThesis;

namespace {

// The largest difference between two sweeps over the samples both solved, each relative to the
// largest magnitude of its quantity in the closed-form sweep (angles in rad, absolute).
struct Agreement {
  double position = 0.0;
  double velocity = 0.0;
  double acceleration = 0.0;
  double angle = 0.0;
  double omega = 0.0;
  double alpha = 0.0;
};

double largest(const std::vector<std::vector<Eigen::Vector2d>>& columns) {
  double s = 0.0;
  for (const auto& column : columns)
    for (const Eigen::Vector2d& v : column) s = std::max(s, v.cwiseAbs().maxCoeff());
  return s;
}

double largest(const std::vector<std::vector<double>>& columns) {
  double s = 0.0;
  for (const auto& column : columns)
    for (const double v : column) s = std::max(s, std::abs(v));
  return s;
}

double worst(const std::vector<std::vector<Eigen::Vector2d>>& a, const std::vector<std::vector<Eigen::Vector2d>>& b,
             std::size_t j) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i][j] - b[i][j]).cwiseAbs().maxCoeff());
  return d;
}

Agreement compare(const SweepResult& closed, const SweepResult& newton) {
  REQUIRE(closed.size() == newton.size());
  Agreement g;
  for (std::size_t j = 0; j < closed.size(); ++j) {
    if (!closed.ok(j) || !newton.ok(j)) continue;
    g.position = std::max(g.position, worst(closed.position, newton.position, j));
    g.velocity = std::max(g.velocity, worst(closed.velocity, newton.velocity, j));
    g.acceleration = std::max(g.acceleration, worst(closed.acceleration, newton.acceleration, j));
    for (std::size_t k = 0; k < closed.linkAngle.size(); ++k) {
      g.angle = std::max(g.angle, std::abs(angleDifference(closed.linkAngle[k][j], newton.linkAngle[k][j])));
      g.omega = std::max(g.omega, std::abs(closed.linkOmega[k][j] - newton.linkOmega[k][j]));
      g.alpha = std::max(g.alpha, std::abs(closed.linkAlpha[k][j] - newton.linkAlpha[k][j]));
    }
  }
  g.position /= largest(closed.position);
  g.velocity /= largest(closed.velocity);
  g.acceleration /= largest(closed.acceleration);
  g.omega /= largest(closed.linkOmega);
  g.alpha /= largest(closed.linkAlpha);
  return g;
}

int mostIterations(const SweepResult& r) {
  int most = 0;
  for (std::size_t j = 1; j < r.size(); ++j) most = std::max(most, r.report[j].iterations);
  return most;
}

std::size_t rrrCount(const Mechanism& m) {
  return static_cast<std::size_t>(std::count_if(
      m.points.begin(), m.points.end(), [](const Point& p) { return std::holds_alternative<RrrPoint>(p.definition); }));
}

// The mechanism with its RRR points made free, guessed where the closed form puts them at `angle`.
Mechanism newtonForm(const Mechanism& m, double angle) {
  const auto reference = solvePose(m, {angle, 0.0, 0.0}, {false, false});
  REQUIRE(reference.ok());
  const Mechanism converted = withNewtonPoints(m, reference->position);
  REQUIRE_FALSE(checkMechanism(converted).has_value());
  return converted;
}

// Solves a mechanism both ways over a full turn every 1° and checks that they agree.
void checkAgreement(const Mechanism& m, double omega, const std::string& name) {
  CAPTURE(name);
  const Mechanism converted = newtonForm(m, 0.0);
  CHECK(converted.constraints.size() == 2 * rrrCount(m));
  // α = ω² makes the tangential and centripetal parts of the accelerations comparable.
  const SweepSpec spec{0.0, 2.0 * kPi, 361, omega, omega * omega};
  const auto closed = sweep(m, spec);
  const auto newton = sweep(converted, spec);
  REQUIRE(closed.ok());
  REQUIRE(newton.ok());
  for (std::size_t j = 0; j < spec.samples; ++j) {
    CAPTURE(j);
    CHECK(closed->report[j].status == PoseStatus::Ok);
    CHECK(newton->report[j].status == PoseStatus::Ok);
  }
  const Agreement g = compare(*closed, *newton);
  // Newton stops once every misfit is below 1e-12 of the size; positions then err by about
  // that over J's smallest singular value (the sine of the transmission angle, ≥ 0.3 here),
  // rates by a small multiple of it. Measured: at most 3.9e-12 (the Stephenson III's link angles) over
  // these examples; 1e-10 leaves a factor 25.
  std::ostringstream figures;
  figures << std::scientific << std::setprecision(2) << name << ": position " << g.position << ", velocity "
          << g.velocity << ", acceleration " << g.acceleration << ", angle " << g.angle << " rad, omega " << g.omega
          << ", alpha " << g.alpha << "; most iterations " << mostIterations(*newton);
  INFO(figures.str());
  CHECK(g.position <= 1e-10);
  CHECK(g.velocity <= 1e-10);
  CHECK(g.acceleration <= 1e-10);
  CHECK(g.angle <= 1e-10);
  CHECK(g.omega <= 1e-10);
  CHECK(g.alpha <= 1e-10);
  // Warm-started from the previous sample 1° back, a point moves ~1.7% of its link; Newton's
  // quadratic convergence takes that to the tolerance in three steps (1e-2 → 1e-4 → 1e-8 →
  // 1e-16 relative), so four per group (one per RRR point here) leaves one spare.
  CHECK(mostIterations(*newton) <= 4 * static_cast<int>(rrrCount(m)));
}

Mechanism fourBar(const FourBarLengths& lengths, Branch branch = Branch::Open) {
  auto m = makeFourBar(lengths, branch);
  REQUIRE(m.ok());
  return *m;
}

}  // namespace

TEST_CASE("Newton agrees with the closed-form dyads on the four-bar examples every 1°", "[newton]") {
  for (const Example& e : examples()) {
    if (e.kind != "four-bar") continue;
    const auto s = asFourBar(e.mechanism);
    REQUIRE(s.has_value());
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      const Mechanism m = withFourBarBranch(e.mechanism, *s, branch);
      checkAgreement(m, e.omega, e.name + (branch == Branch::Open ? " open" : " crossed"));
    }
  }
}

TEST_CASE("Newton agrees with the closed form on the dyad six-bars (two groups each)", "[newton]") {
  for (const Example& e : examples())
    if (e.kind != "four-bar" && rrrCount(e.mechanism) >= 2) checkAgreement(e.mechanism, e.omega, e.name);
}

TEST_CASE("Newton reports non-convergence where the linkage cannot close, as the dyads do", "[newton]") {
  // A double rocker (the coupler is shortest): the input assembles for |θ| in [11.75°, 85.46°]
  // only, where |BO4| lies between 45 − 30 and 45 + 30 mm.
  const Mechanism m = fourBar({60.0, 50.0, 30.0, 45.0});
  const Mechanism converted = newtonForm(m, degToRad(45.0));
  const SweepSpec spec{degToRad(45.0), degToRad(405.0), 361, 1.0, 0.0};
  const auto closed = sweep(m, spec);
  const auto newton = sweep(converted, spec);
  REQUIRE(closed.ok());
  REQUIRE(newton.ok());
  CHECK(closed->notAssembled.size() == 2);
  CHECK(newton->notAssembled == closed->notAssembled);
  std::size_t failed = 0;
  for (std::size_t j = 0; j < spec.samples; ++j) {
    CAPTURE(j);
    CHECK(newton->report[j].status == closed->report[j].status);
    if (newton->report[j].status != PoseStatus::NotAssemblable) continue;
    ++failed;
    CHECK(newton->report[j].failure == AssemblyFailure::NoConvergence);
    CHECK(newton->report[j].culprit == fourbar::kC);
    CHECK(newton->report[j].residual > 1e-3);  // it stops well away from closing: no wrong pose
  }
  CHECK(failed > 50);
  // Up to the first failure both follow the same branch; positions agree there.
  for (std::size_t j = 0; j < spec.samples && closed->assembled(j); ++j) {
    CAPTURE(j);
    CHECK((newton->position[fourbar::kC.index][j] - closed->position[fourbar::kC.index][j]).norm() <= 1e-10 * 60.0);
  }
  REQUIRE(newton->firstFailure.has_value());
  CHECK(newton->firstFailure->find("C cannot be assembled at crank angle") == 0);
  CHECK(newton->firstFailure->find("Newton did not converge (residual ") != std::string::npos);
  CHECK(newton->firstFailure->find("the linkage probably cannot close here") != std::string::npos);
}

TEST_CASE("A stretched length is reported as NoConvergence, not as a wrong pose", "[newton][errors]") {
  Mechanism m = newtonForm(fourBar(kThesis), 0.0);
  m.constraints.back().length = 200.0;  // the rocker O4–C: no circle of 200 about O4 meets the coupler's
  Pose pose;
  preparePose(m, pose);
  const PoseReport r = solvePoseInto(m, {degToRad(200.0), 1.0, 0.0}, {}, pose);
  CHECK(r.status == PoseStatus::NotAssemblable);
  CHECK(r.culprit == fourbar::kC);
  CHECK(r.failure == AssemblyFailure::NoConvergence);
  CHECK(r.iterations >= 1);
  CHECK(r.iterations <= NewtonSettings{}.maxIterations);
  // C can be at most |O4B| + coupler ≈ 83.9 + 70 mm from O4 at 200°: 46 mm short of 200.
  CHECK(r.residual > 10.0);
  CHECK_FALSE(pose.assembled);
  const std::string message = describeFailure(m, r, pose, degToRad(200.0));
  CAPTURE(message);
  CHECK(message.find("C cannot be assembled at crank angle 200°: Newton did not converge (residual ") == 0);
  CHECK(message.find(" mm after ") != std::string::npos);
  CHECK(message.find(", worst at ") != std::string::npos);  // the coupler or the rocker
  CHECK(message.find("); the linkage probably cannot close here") != std::string::npos);
  const auto viaSolvePose = solvePose(m, {degToRad(200.0), 1.0, 0.0});
  REQUIRE_FALSE(viaSolvePose.ok());
  CHECK(viaSolvePose.error().code == ErrorCode::NotAssemblable);
  CHECK(viaSolvePose.error().field == "C");
}

TEST_CASE("A singular Jacobian at a converged pose is reported Singular, as the dyad's toggle", "[newton]") {
  // A parallelogram (change point): at 0° crank, coupler and rocker all lie on the x axis.
  const Mechanism m = fourBar({60.0, 25.0, 60.0, 25.0});
  const Mechanism converted = newtonForm(m, degToRad(20.0));
  Pose pose;
  preparePose(converted, pose);
  REQUIRE(solvePoseInto(converted, {degToRad(20.0), 1.0, 0.0}, {}, pose).status == PoseStatus::Ok);
  const PoseReport r = solvePoseInto(converted, {0.0, 1.0, 0.0}, {}, pose);
  CHECK(r.status == PoseStatus::Singular);
  CHECK(r.culprit == fourbar::kC);
  CHECK(r.failure == AssemblyFailure::None);
  CHECK(pose.assembled);
  // At a double root Newton converges linearly and the misfit is quadratic in the error, so
  // a misfit of 1e-12·60 mm leaves C about √(2·60·6e-11) ≈ 1e-4 mm off: the toggle's own
  // sensitivity, as in the closed form's square root.
  CHECK((pose.position[fourbar::kC.index] - Eigen::Vector2d(85.0, 0.0)).norm() <= 1e-3);
  CHECK(solvePose(m, {0.0, 1.0, 0.0}).error().code == ErrorCode::Singular);
  const std::string message = describeFailure(converted, r, pose, 0.0);
  CHECK(message ==
        "C is at a singular position at crank angle 0°: its distance constraints do not fix its motion (the "
        "linkage could move with the crank held, or a link is at a toggle), so velocity and acceleration are "
        "undefined there");
  // Positions alone need no rates, so the same pose is simply Ok.
  CHECK(solvePoseInto(converted, {0.0, 0.0, 0.0}, {false, false}, pose).status == PoseStatus::Ok);
}

TEST_CASE("Newton starts from the prediction, else the pose's last assembly, else the guesses", "[newton]") {
  const Mechanism m = newtonForm(fourBar(kThesis), 0.0);
  Pose pose;
  preparePose(m, pose);
  CHECK_FALSE(pose.assembled);
  // From the guesses (the closed form's pose at 0°) at 0°: nothing to do.
  PoseReport r = solvePoseInto(m, {0.0, 1.0, 0.0}, {}, pose);
  CHECK(r.status == PoseStatus::Ok);
  CHECK(r.iterations == 0);
  CHECK(pose.assembled);
  // Warm from that pose at 1°: a few steps.
  r = solvePoseInto(m, {degToRad(1.0), 1.0, 0.0}, {}, pose);
  CHECK(r.iterations >= 1);
  CHECK(r.iterations <= 4);
  // The same angle again: already there.
  const Pose before = pose;
  r = solvePoseInto(m, {degToRad(1.0), 1.0, 0.0}, {}, pose);
  CHECK(r.iterations == 0);
  CHECK(pose == before);  // Pose stays a meaningful value: same input, same result
  // A prediction exactly at the solution costs nothing either, wherever the pose was.
  const std::vector<Eigen::Vector2d> predicted = before.position;
  preparePose(m, pose);
  r = solvePoseInto(m, {degToRad(1.0), 1.0, 0.0}, {}, pose, BranchGuide{{}, predicted});
  CHECK(r.iterations == 0);
  CHECK(pose.position == before.position);
}

TEST_CASE("Newton's cost follows its tolerance, and its accuracy too", "[newton]") {
  const Mechanism closedForm = fourBar(kThesis);
  const Mechanism m = newtonForm(closedForm, 0.0);
  const auto exact = solvePose(closedForm, {degToRad(60.0), 1.0, 0.0});
  REQUIRE(exact.ok());
  int lastIterations = 0;
  for (const double tolerance : {1e-4, 1e-8, 1e-12, 1e-14}) {
    CAPTURE(tolerance);
    SolveRequest request;
    request.newton.tolerance = tolerance;
    Pose pose;
    preparePose(m, pose);
    const PoseReport r = solvePoseInto(m, {degToRad(60.0), 1.0, 0.0}, request, pose);  // from the 0° guess
    REQUIRE(r.status == PoseStatus::Ok);
    CHECK(r.iterations >= lastIterations);
    lastIterations = r.iterations;
    // The size here is the frame, 60 mm; the error is below the misfit over J's smallest
    // singular value (the transmission angle's sine, ≥ 0.4 at 60°), with room.
    CHECK(r.residual <= tolerance * 60.0);
    CHECK((pose.position[fourbar::kC.index] - exact->position[fourbar::kC.index]).norm() <= 10.0 * tolerance * 60.0);
  }
  // A cap of one step from 60° away cannot converge: reported, not hidden.
  SolveRequest capped;
  capped.newton.maxIterations = 1;
  Pose pose;
  preparePose(m, pose);
  const PoseReport r = solvePoseInto(m, {degToRad(60.0), 1.0, 0.0}, capped, pose);
  CHECK(r.status == PoseStatus::NotAssemblable);
  CHECK(r.failure == AssemblyFailure::NoConvergence);
  CHECK(r.iterations == 1);
}

TEST_CASE("checkNewtonSettings names the bad setting", "[newton][errors]") {
  CHECK_FALSE(checkNewtonSettings({}).has_value());
  CHECK_FALSE(checkNewtonSettings({1e-15, 1}).has_value());
  const auto tolerance = checkNewtonSettings({0.0, 50});
  REQUIRE(tolerance.has_value());
  CHECK(tolerance->field == "newton.tolerance");
  CHECK(tolerance->message == "newton.tolerance must be at least 1e-15 and below 1 (got 0)");
  CHECK(checkNewtonSettings({std::numeric_limits<double>::quiet_NaN(), 50})->field == "newton.tolerance");
  const auto iterations = checkNewtonSettings({1e-12, 0});
  REQUIRE(iterations.has_value());
  CHECK(iterations->message == "newton.maxIterations must be from 1 to 1000 (got 0)");
  SolveRequest request;
  request.newton.maxIterations = -3;
  const auto viaSolvePose = solvePose(fourBar(kThesis), {0.0, 1.0, 0.0}, request);
  REQUIRE_FALSE(viaSolvePose.ok());
  CHECK(viaSolvePose.error().field == "newton.maxIterations");
}

TEST_CASE("checkMechanism names what is wrong with free points and distance constraints", "[newton][errors]") {
  const Mechanism valid = newtonForm(fourBar(kThesis), 0.0);  // O2, O4, B, then C free on B–C, O4–C
  REQUIRE_FALSE(checkMechanism(valid).has_value());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto check = [&](const std::function<void(Mechanism&)>& breakIt, ErrorCode code, const std::string& field,
                         const std::string& message) {
    Mechanism m = valid;
    breakIt(m);
    const auto e = checkMechanism(m);
    REQUIRE(e.has_value());
    CHECK(e->code == code);
    CHECK(e->field == field);
    CHECK(e->message == message);
  };
  check([](Mechanism& m) { m.constraints[0].second = PointId{9}; }, ErrorCode::InvalidStructure, "constraints[0]",
        "constraints[0] refers to a point that does not exist");
  check([](Mechanism& m) { m.constraints[0].first = PointId{3}; }, ErrorCode::InvalidStructure, "constraints[0]",
        "constraints[0] joins point C to itself");
  check([](Mechanism& m) { m.constraints[1].length = -70.0; }, ErrorCode::InvalidValue, "constraints[1].length",
        "constraints[1].length must be positive and finite (got -70)");
  check([&](Mechanism& m) { m.constraints[1].length = nan; }, ErrorCode::InvalidValue, "constraints[1].length",
        "constraints[1].length must be positive and finite (got undefined)");
  check(
      [](Mechanism& m) {
        m.constraints.push_back({PointId{0}, PointId{2}, 25.0});
      },
      ErrorCode::InvalidStructure, "constraints[2]",
      "constraints[2] joins O2 and B, but the later of them, B, is not a free point: a distance constraint must "
      "close on a free point");
  check([&](Mechanism& m) { std::get<FreePoint>(m.points[3].definition).guess.y() = nan; }, ErrorCode::InvalidValue,
        "points[3].guess.y", "points[3].guess.y must be finite (got undefined)");
  check(
      [](Mechanism& m) { m.constraints.pop_back(); }, ErrorCode::InvalidStructure, "constraints",
      "constraints must hold free points C (points[3..3]) with exactly 2 distance constraints, two per point (got 1)");
  // A free point D right after C joins C's group: 4 unknowns need 4 constraints, and D two of them.
  check(
      [](Mechanism& m) {
        m.points.push_back({"D", FreePoint{Eigen::Vector2d(90.0, 40.0)}});
        m.constraints.push_back({PointId{3}, PointId{4}, 30.0});
      },
      ErrorCode::InvalidStructure, "constraints",
      "constraints must hold free points C, D (points[3..4]) with exactly 4 distance constraints, two per point (got "
      "3)");
  check(
      [](Mechanism& m) {
        m.points.push_back({"D", FreePoint{Eigen::Vector2d(90.0, 40.0)}});
        m.constraints.push_back({PointId{3}, PointId{4}, 30.0});
        m.constraints.push_back({PointId{2}, PointId{3}, 70.0});
      },
      ErrorCode::InvalidStructure, "points[4]",
      "points[4] (D) is held by 1 distance constraint(s) of its group; a free point needs at least two");
  check(
      [](Mechanism& m) {
        for (int k = 0; k < 8; ++k) m.points.push_back({"F" + std::to_string(k), FreePoint{}});
      },
      ErrorCode::InvalidStructure, "points[3]",
      "points[3] starts free points C, F0, F1, F2, F3, F4, F5, F6, F7 (points[3..11]): a group of consecutive free "
      "points may hold at most 8 (got 9)");
  // A link may join two points held by a distance constraint, and only then.
  Mechanism linked = valid;
  linked.links.push_back({"extra", PointId{0}, PointId{3}});
  REQUIRE(checkMechanism(linked).has_value());
  CHECK(checkMechanism(linked)->message == "links[3] joins points that are not held at a fixed distance");
}
