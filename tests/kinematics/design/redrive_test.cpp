// Driving a linkage from another joint (design/redrive.h): the new linkage, driven at the rate
// the new driver had, moves exactly as the old one: every point's position, velocity and
// acceleration equal, by name. The old driver and its neighbour trade roles and nothing else
// changes; a point that is not a choice is refused naming "driver".

#include "kinematics/design/redrive.h"

#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;
using Eigen::Vector2d;

namespace {

double cross(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

Pose solved(const Mechanism& m, const DriverState& state) {
  const Result<Pose> pose = solvePose(m, state);
  REQUIRE(pose.ok());
  return pose.value();
}

// The new driver's rate and acceleration in `pose` of the old linkage: a crank's ω and α
// about its pivot, a path point's ṡ and s̈ along its straight path.
DriverState newDriverState(const Mechanism& old, const Pose& pose, const Mechanism& next, double input) {
  const PointId driver = driverPoint(next).value();
  const PointId before = old.findPoint(next.points[driver.index].name).value();
  const Vector2d v = pose.velocity[before.index];
  const Vector2d a = pose.acceleration[before.index];
  const PointDefinition& d = next.points[driver.index].definition;
  if (const auto* crank = std::get_if<CrankPoint>(&d)) {
    const PointId pivot = old.findPoint(next.points[crank->pivot.index].name).value();
    const Vector2d r = pose.position[before.index] - pose.position[pivot.index];
    return {input, cross(r, v) / r.squaredNorm(), cross(r, a) / r.squaredNorm()};
  }
  const Vector2d u = pathAt(std::get<PathPoint>(d).path, input).tangent;
  return {input, v.dot(u), a.dot(u)};
}

// Positions, velocities and accelerations of every point of `old` at `state` equal the
// redriven linkage's at the new driver's input and rates.
void expectSameMotion(const Design& old, const DriverState& state, const Redriven& next) {
  const Pose before = solved(old.mechanism, state);
  const Mechanism& m = next.design.mechanism;
  const Pose after = solved(m, newDriverState(old.mechanism, before, m, next.input));
  REQUIRE(m.points.size() == old.mechanism.points.size());
  for (std::size_t i = 0; i < old.mechanism.points.size(); ++i) {
    const std::string& name = old.mechanism.points[i].name;
    INFO("point " << name);
    const std::size_t j = m.findPoint(name).value().index;
    const double scale = 1.0 + before.acceleration[i].norm();
    CHECK((after.position[j] - before.position[i]).norm() <= 1e-9 * (1.0 + before.position[i].norm()));
    CHECK((after.velocity[j] - before.velocity[i]).norm() <= 1e-9 * (1.0 + before.velocity[i].norm()));
    CHECK((after.acceleration[j] - before.acceleration[i]).norm() <= 1e-9 * scale);
  }
}

std::vector<std::string> descriptions(const Mechanism& m) {
  std::vector<std::string> out;
  for (const DriverChoice& c : driverChoices(m)) out.push_back(c.description);
  return out;
}

}  // namespace

TEST_CASE("A four-bar driven from its rocker moves as when driven from its crank", "[design][redrive]") {
  const Design thesis = designForExample("thesis-crank-rocker").value();
  const Mechanism& m = thesis.mechanism;
  CHECK(descriptions(m) == std::vector<std::string>{"crank about O2 (angle)", "rocker about O4 (angle)"});
  const PointId c = m.findPoint("C").value();
  for (const double deg : {0.0, 30.0, 100.0, 200.0, 290.0}) {
    INFO("crank at " << deg << " deg");
    const double q = degToRad(deg);
    const auto next = driveFrom(thesis, c, q);
    REQUIRE(next.ok());
    expectSameMotion(thesis, {q, 1.3, 0.7}, *next);
    // Still a four-bar, read from its structure: its crank now turns about O4.
    const auto fourBar = asFourBar(next->design.mechanism);
    REQUIRE(fourBar.has_value());
    CHECK(next->design.mechanism.points[fourBar->o2.index].name == "O4");
    CHECK(inputName(next->design.mechanism) == "rocker angle");
    CHECK(next->input >= 0.0);
    CHECK(next->input < 2.0 * kPi);
    // And back: driven from B again, the crank-rocker moves as it did.
    const PointId b = next->design.mechanism.findPoint("B").value();
    CHECK(descriptions(next->design.mechanism) ==
          std::vector<std::string>{"rocker about O4 (angle)", "crank about O2 (angle)"});
    const auto back = driveFrom(next->design, b, next->input);
    REQUIRE(back.ok());
    CHECK(back->input == Approx(q).margin(1e-12));
    CHECK(asFourBar(back->design.mechanism)->branch == asFourBar(m)->branch);
  }
}

TEST_CASE("A slider-crank driven from its piston: a path over its stroke, the same motion", "[design][redrive]") {
  const Design ls3 = designForExample("ls3-engine").value();
  const Mechanism& m = ls3.mechanism;
  const PointId c = m.findPoint("C").value();
  CHECK(descriptions(m).back() == "C along its guide (position)");
  const auto sc = asSliderCrank(m).value();
  const double crank = std::get<CrankPoint>(m.points[sc.b.index].definition).length;
  for (const double deg : {20.0, 135.0, 250.0}) {
    INFO("crank at " << deg << " deg");
    const double q = degToRad(deg);
    const auto next = driveFrom(ls3, c, q);
    REQUIRE(next.ok());
    expectSameMotion(ls3, {q, 40.0, -3.0}, *next);
    const Mechanism& piston = next->design.mechanism;
    CHECK(inputKind(piston) == InputKind::Length);
    // The path is the stroke, dead centre to dead centre: twice the crank of an in-line engine.
    const PathShape& path = std::get<PathPoint>(piston.points[driverPoint(piston)->index].definition).path;
    CHECK(pathLength(path) == Approx(2.0 * crank).epsilon(1e-12));
    CHECK(next->design.fromDeg == Approx(0.01 * 2.0 * crank));
    CHECK(next->design.toDeg == Approx(0.99 * 2.0 * crank));
    // Back to the crank: the engine as it was.
    const auto back = driveFrom(next->design, piston.findPoint("B").value(), next->input);
    REQUIRE(back.ok());
    CHECK(back->input == Approx(q).margin(1e-9));
    CHECK(asSliderCrank(back->design.mechanism).has_value());
  }
}

TEST_CASE("The two-link arm driven from its shoulder moves its tip along the line", "[design][redrive]") {
  const Design arm = designForExample("seed-arm").value();
  const Mechanism& m = arm.mechanism;
  CHECK(descriptions(m) == std::vector<std::string>{"tip along its path (position)", "upper about O (angle)"});
  const auto next = driveFrom(arm, m.findPoint("elbow").value(), 0.1);
  REQUIRE(next.ok());
  expectSameMotion(arm, {0.1, 2.0, 5.0}, *next);
  CHECK(inputKind(next->design.mechanism) == InputKind::Angle);
  CHECK_FALSE(next->design.time.has_value());
  CHECK(next->design.toDeg - next->design.fromDeg == 360.0);
  // The tip's speed 2 m/s becomes the shoulder's 2 m/s over the upper arm, 0.3 m.
  CHECK(next->design.omega == Approx(std::abs(arm.omega) / 0.3));
}

TEST_CASE("Points a linkage cannot be driven from are refused, naming the driver", "[design][redrive][errors]") {
  const Design thesis = designForExample("thesis-crank-rocker").value();
  for (const char* name : {"O2", "O4"}) {
    INFO(name);
    const auto id = thesis.mechanism.findPoint(name);
    REQUIRE(id.has_value());
    const auto r = driveFrom(thesis, *id, 0.0);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().field == "driver");
    CHECK_THAT(r.error().message, Catch::Contains(std::string("cannot be driven from ") + name));
  }
  CHECK_FALSE(driveFrom(thesis, PointId{99}, 0.0).ok());
  // Its own driver: the design as it is.
  const auto same = driveFrom(thesis, thesis.mechanism.findPoint("B").value(), 0.25);
  REQUIRE(same.ok());
  CHECK(same->design == thesis);
  CHECK(same->input == 0.25);
  // An actuator has no neighbour to hand over to; a six-bar's far dyads are not next to the crank.
  CHECK(driverChoices(designForExample("excavator-boom")->mechanism).size() == 1);
  // Where the linkage cannot be assembled there is no pose to keep.
  const Design triple = fourBarDesign({60, 20, 25, 30}).value();
  const auto r = driveFrom(triple, triple.mechanism.findPoint("C").value(), kPi);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().field == "driver");
}

TEST_CASE("A slider's mass cannot ride a path driver: the swap is refused, naming the mass", "[design][redrive]") {
  Design ls3 = designForExample("ls3-engine").value();
  ls3.dynamics.sliders = {{"C", 0, 0.5, 0.0}};
  REQUIRE_FALSE(checkDesign(ls3).has_value());
  const auto r = driveFrom(ls3, ls3.mechanism.findPoint("C").value(), 1.0);
  REQUIRE_FALSE(r.ok());
  CHECK(r.error().field == "dynamics.sliders[0].point");
}

TEST_CASE("A six-bar's second loop follows its first four-bar driven from the rocker", "[design][redrive]") {
  for (const char* name : {"watt-i", "watt-ii", "stephenson-iii"}) {
    INFO(name);
    const Design six = designForExample(name).value();
    const PointId c = six.mechanism.findPoint("C").value();
    const double q = degToRad(75.0);
    const auto next = driveFrom(six, c, q);
    REQUIRE(next.ok());
    expectSameMotion(six, {q, 2.0, 1.5}, *next);
  }
}
