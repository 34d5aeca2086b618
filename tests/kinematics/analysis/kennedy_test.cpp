// Kennedy's circle diagram on every built-in linkage, checked against the pose solver's exact
// velocities, not against itself: each body moves as a rigid body (from the solver's point
// velocities), so at a finite centre Iij bodies i and j have one velocity, and at a centre at
// infinity they turn together and their relative velocity is normal to its direction. The
// velocity ratio equals the solver's output rate over the crank's. Then the numbering the
// texts use, what Kennedy's theorem cannot reach, and the order-independence of the passes.

#include "kinematics/analysis/kennedy.h"
#include "kinematics/analysis/centre_model.h"
#include "kinematics/analysis/instant_centres.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/rigid_bodies.h"

#include "tests/support/catch.h"

#include <cmath>
#include <string>
#include <vector>

using namespace linkwright::kinematics;

namespace {

// A body's velocity field from the solver: v(P) = v(O) + ω ẑ×(P − O).
struct Motion {
  double omega = 0.0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  Eigen::Vector2d at(const Eigen::Vector2d& p) const { return velocity + omega * perp(p - origin); }
};

Motion motionOf(const BodyModel& bodies, BodyId id, const Pose& pose) {
  const Body& body = bodies.bodies[id.index];
  if (body.kind == BodyKind::Ground) return {};
  const Eigen::Vector2d p1 = pose.position[body.reference.index], v1 = pose.velocity[body.reference.index];
  if (body.kind == BodyKind::Slider)  // a block turns with its guide body, pinned at its point
    return {motionOf(bodies, body.turnsWith, pose).omega, p1, v1};
  const Eigen::Vector2d r = pose.position[body.second.index] - p1;
  const Eigen::Vector2d dv = pose.velocity[body.second.index] - v1;
  return {cross(r, dv) / r.squaredNorm(), p1, v1};
}

// The solved motions of the numbered bodies, index = number − 1.
std::vector<Motion> motions(const Mechanism& m, const CentreModel& model, const Pose& pose) {
  const BodyModel bodies = bodiesOf(m).value();
  std::vector<Motion> out;
  for (const BodyId id : model.bodyIds) out.push_back(motionOf(bodies, id, pose));
  return out;
}

// Every located centre agrees with the solver's velocities (crank at 1 rad/s, so velocities
// are of the order of the linkage's size); returns how many were located.
std::size_t checkAgainstSolver(const InstantCentres& c, const std::vector<Motion>& v) {
  std::size_t located = 0;
  const double tolerance = 1e-9 * c.scale;
  for (std::size_t i = 1; i <= c.bodyCount(); ++i)
    for (std::size_t j = i + 1; j <= c.bodyCount(); ++j) {
      CAPTURE(i, j);
      const InstantCentre& centre = c.centre(i, j);
      const Motion &a = v[i - 1], &b = v[j - 1];
      if (centre.kind == CentreKind::Finite) {
        CHECK((a.at(centre.position) - b.at(centre.position)).norm() <= tolerance);
        ++located;
      } else if (centre.kind == CentreKind::AtInfinity) {
        CHECK(std::abs(a.omega - b.omega) <= 1e-9);
        CHECK(std::abs((a.velocity - b.at(a.origin)).dot(centre.direction)) <= tolerance);
        ++located;
      }
    }
  return located;
}

}  // namespace

TEST_CASE("every centre of every crank-driven example is located and moves as the solver says",
          "[analysis][centres][kennedy]") {
  const std::string name =
      GENERATE(as<std::string>{}, "thesis-crank-rocker", "ls3-engine", "shaper", "whitworth", "watt-i", "watt-ii",
               "stephenson-i", "stephenson-iii", "stephenson-ii", "stephenson-iii-triad");
  CAPTURE(name);
  const Mechanism m = findExample(name)->mechanism;
  const CentreModel model = centreModel(m).value();
  REQUIRE(model.ratio.exists());
  REQUIRE(model.ratio.input == 2);
  std::size_t poses = 0;
  for (int deg = 7; deg < 360; deg += 29) {
    CAPTURE(deg);
    const auto pose = solvePose(m, {degToRad(deg), 1.0, 0.0});
    if (!pose) continue;  // beyond a rocking crank's reach
    ++poses;
    const auto centres = instantCentres(m, *pose);
    REQUIRE(centres);
    CHECK(*centres == instantCentres(m, model, *pose));
    const std::size_t n = centres->bodyCount();
    const std::vector<Motion> v = motions(m, model, *pose);
    CHECK(checkAgainstSolver(*centres, v) == n * (n - 1) / 2);  // Kennedy closes: all located
    // The ratio the centres give is the solver's output rate over the crank's.
    const MechanicalAdvantage ma = mechanicalAdvantage(*centres);
    REQUIRE(ma.velocityRatio.kind == RatioKind::Finite);
    const Motion& out = v[centres->ratio.output - 1];
    const double expected = centres->ratio.outputSlides ? out.velocity.dot(centres->outputDirection) : out.omega;
    CHECK(ma.velocityRatio.value == Approx(expected).margin(1e-9 * centres->scale));
  }
  CHECK(poses >= 6);
}

TEST_CASE("centres solved into reused memory equal fresh ones, across poses and linkages",
          "[analysis][centres][kennedy]") {
  InstantCentres reused;  // as a sweep reuses it: a six-bar's fifteen centres, then a four-bar's six
  for (const char* name : {"watt-ii", "shaper", "thesis-crank-rocker", "ls3-engine"}) {
    CAPTURE(name);
    const Mechanism m = findExample(name)->mechanism;
    const CentreModel model = centreModel(m).value();
    for (const double deg : {15.0, 200.0}) {
      const auto pose = solvePose(m, {degToRad(deg), 0.0, 0.0}, SolveRequest{false, false});
      REQUIRE(pose);
      instantCentresInto(m, model, *pose, reused);
      CHECK(reused == instantCentres(m, model, *pose));
    }
  }
}

TEST_CASE("bodies are numbered as the texts number them, and named", "[analysis][centres][kennedy]") {
  const auto names = [](const char* example) { return centreModel(findExample(example)->mechanism).value().bodies; };
  CHECK(names("thesis-crank-rocker") == std::vector<std::string>{"frame", "crank", "coupler", "rocker"});
  CHECK(names("ls3-engine") == std::vector<std::string>{"frame", "crank", "rod", "slider C"});
  // Norton's crank-shaper: 2 crank, 3 block in the slot, 4 slotted rocker, 5 link, 6 ram.
  CHECK(names("shaper") == std::vector<std::string>{"frame", "crank", "block B", "rocker", "link", "slider R"});
  const CentreModel shaper = centreModel(findExample("shaper")->mechanism).value();
  CHECK(shaper.ratio == RatioBodies{2, 6, true});
  CHECK(shaper.centrodeBody == 5);
  const CentreModel watt = centreModel(findExample("watt-ii")->mechanism).value();
  CHECK(watt.ratio == RatioBodies{2, 6, false});  // the second rocker, about O6
  CHECK(watt.centrodeBody == 3);
}

TEST_CASE("centres Kennedy's theorem cannot reach stay unresolved, and the ratios need a crank",
          "[analysis][centres][kennedy]") {
  // A two-link arm has two freedoms: the frame and the forearm share no centre three lines fix.
  const Mechanism arm = findExample("seed-arm")->mechanism;
  const auto pose = solvePose(arm, {0.1, 0.0, 0.0}, SolveRequest{false, false});
  REQUIRE(pose);
  const auto c = instantCentres(arm, *pose);
  REQUIRE(c);
  REQUIRE(c->bodyCount() == 3);
  std::size_t unresolved = 0;
  for (const InstantCentre& centre : c->centres) unresolved += centre.kind == CentreKind::Unresolved;
  CHECK(unresolved == 1);
  CHECK_FALSE(c->ratio.exists());
  CHECK(mechanicalAdvantage(*c).velocityRatio.kind == RatioKind::Undefined);
}

TEST_CASE("the circle diagram: parallel lines meet at infinity, coincident ones leave the centre indeterminate",
          "[analysis][centres][kennedy]") {
  // Four bodies, the four-bar's primaries placed by hand: a parallelogram at 90°.
  InstantCentres c;
  c.bodies = {"frame", "crank", "coupler", "rocker"};
  c.centres.resize(6);
  c.origins.resize(6);
  c.scale = 60.0;
  const auto pin = [&](std::size_t i, std::size_t j, Eigen::Vector2d at) {
    c.centres[c.pairIndex(i, j)] = {CentreKind::Finite, at, Eigen::Vector2d::Zero()};
    c.origins[c.pairIndex(i, j)].rule = CentreRule::Pin;
  };
  pin(1, 2, {0, 0});
  pin(1, 4, {60, 0});
  pin(2, 3, {0, 25});
  pin(3, 4, {60, 25});
  InstantCentres flat = c;
  completeByKennedy(c);
  CHECK(c.centre(1, 3) == centreAtInfinity({0, 1}));  // the coupler translates, along x
  CHECK(c.centre(2, 4) == centreAtInfinity({1, 0}));
  CHECK(c.origin(1, 3).via == std::array<std::size_t, 2>{2, 4});
  CHECK(c.origin(2, 4).via == std::array<std::size_t, 2>{1, 3});
  // All joints on one line: both secondary centres are indeterminate, never a number.
  flat.centres[flat.pairIndex(2, 3)].position = {25, 0};
  flat.centres[flat.pairIndex(3, 4)].position = {95, 0};
  completeByKennedy(flat);
  CHECK(flat.centre(1, 3).kind == CentreKind::Indeterminate);
  CHECK(flat.centre(2, 4).kind == CentreKind::Indeterminate);
  CHECK(flat.centre(1, 3).position == Eigen::Vector2d::Zero());
  // A slide with no direction (a link whose ends meet) is no point at infinity.
  CHECK(centreAtInfinity({0, 0}).kind == CentreKind::Indeterminate);
  CHECK(centreAtInfinity({std::nan(""), 1}).kind == CentreKind::Indeterminate);
  CHECK(centreAtInfinity({-3, 0}) == InstantCentre{CentreKind::AtInfinity, {0, 0}, {1, 0}});
}
