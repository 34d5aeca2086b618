// Bodies and joints found from point definitions (rigid_bodies.h): counts, which points each
// body holds, the hub rule, the driven body and the Gruebler count of every kind of linkage.

#include "kinematics/solve/rigid_bodies.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/sixbar_newton.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <algorithm>

using namespace linkwright::kinematics;

namespace {

std::vector<std::string> pointNames(const Mechanism& m, const Body& b) {
  std::vector<std::string> names;
  for (const PointId p : b.points) names.push_back(m.points[p.index].name);
  return names;
}

std::vector<std::string> jointNames(const BodyModel& model) {
  std::vector<std::string> names;
  for (const auto& j : model.revolutes) names.push_back(j.name);
  for (const auto& j : model.prismatics) names.push_back("P:" + j.name);
  return names;
}

using Names = std::vector<std::string>;

}  // namespace

TEST_CASE("bodiesOf: a four-bar has ground, crank, coupler, rocker and four pins", "[dynamics]") {
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open, "mm", CouplerPointSpec{35.0, 20.0}).value();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 4);
  CHECK(pointNames(m, model->bodies[0]) == Names{"O2", "O4"});
  CHECK(pointNames(m, model->bodies[1]) == Names{"O2", "B"});
  CHECK(pointNames(m, model->bodies[2]) == Names{"B", "C", "P"});  // the coupler point rides on it
  CHECK(pointNames(m, model->bodies[3]) == Names{"O4", "C"});
  CHECK(model->bodies[2].name == "coupler");
  CHECK(jointNames(*model) == Names{"O2", "O4", "B", "C"});
  // Hubs: the ground at its pivots, else the lower body (crank at B, coupler at C).
  CHECK(model->revolutes[2].hub == BodyId{1});
  CHECK(model->revolutes[2].body == BodyId{2});
  CHECK(model->revolutes[3].hub == BodyId{2});
  CHECK(model->revolutes[3].body == BodyId{3});
  CHECK(model->drive.body == BodyId{1});
  CHECK(model->drive.kind == DriveKind::Crank);
  CHECK(model->linkBody == std::vector<BodyId>{BodyId{1}, BodyId{2}, BodyId{3}});
  CHECK(model->mobility() == 1);
  CHECK(model->unknowns() == 9);  // seed 004's 9×9 system
  CHECK(model->equations() == 9);
}

TEST_CASE("bodiesOf: a slider-crank's piston is a block on the ground guide", "[dynamics]") {
  const Mechanism m = makeSliderCrank(kLs3Engine).value();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 4);
  CHECK(model->bodies[3].kind == BodyKind::Slider);
  CHECK(pointNames(m, model->bodies[3]) == Names{"C"});
  CHECK(jointNames(*model) == Names{"O2", "B", "C", "P:C"});
  CHECK(model->prismatics[0].guide == kGroundBody);
  CHECK(model->prismatics[0].block == BodyId{3});
  CHECK(model->revolutes[2].hub == BodyId{2});  // rod holds the piston's pin
  CHECK(model->mobility() == 1);
}

TEST_CASE("bodiesOf: a shaper's slotted rocker carries a block pinned at the crank tip", "[dynamics]") {
  const Mechanism m = makeShaper(kSeedShaper).value();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 6);  // ground, crank, rocker, link, block at B, ram
  CHECK(jointNames(*model) == Names{"O2", "O4", "B", "D", "R", "P:B_D", "P:R"});
  const PrismaticJoint& slot = model->prismatics[0];
  CHECK(slot.pin == shaper::kB);
  CHECK(slot.guide == model->linkBody[shaper::kRocker.index]);
  CHECK(model->bodies[slot.block.index].turnsWith == slot.guide);
  CHECK(model->prismatics[1].guide == kGroundBody);
  CHECK(model->mobility() == 1);
}

TEST_CASE("bodiesOf: a Watt II six-bar has a ternary rocker and a ground ternary", "[dynamics]") {
  const Mechanism m = makeSixBar(kWattIISixBar).value();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 6);
  CHECK(pointNames(m, model->bodies[0]) == Names{"O2", "O4", "O6"});
  CHECK(pointNames(m, model->bodies[model->linkBody[fourbar::kRocker.index].index]) == Names{"O4", "C", "P"});
  CHECK(model->revolutes.size() == 7);
  CHECK(model->prismatics.empty());
  CHECK(model->mobility() == 1);
}

TEST_CASE("bodiesOf: the Stephenson II's ternary plates come from constraint triangles", "[dynamics]") {
  const Mechanism m = makeStephensonIINewton().value();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 6);  // ground, crank, two ternaries, link5, link6
  CHECK(pointNames(m, model->bodies[model->linkBody[stephenson2::kCoupler.index].index]) == Names{"J1", "J2", "J3"});
  CHECK(pointNames(m, model->bodies[model->linkBody[stephenson2::kRocker.index].index]) == Names{"J5", "J4", "J6"});
  CHECK(jointNames(*model) == Names{"J0", "J5", "J1", "J2", "J3", "J4", "J6"});
  CHECK(model->mobility() == 1);
}

TEST_CASE("bodiesOf: a ternary plate made of constraints alone, with no link on it", "[dynamics]") {
  // The Stephenson II without its coupler link: the triangle J1 J2 J3 is still one body.
  Mechanism m = makeStephensonIINewton().value();
  m.links.erase(m.links.begin() + static_cast<std::ptrdiff_t>(stephenson2::kCoupler.index));
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 6);
  const auto plate = std::find_if(model->bodies.begin(), model->bodies.end(), [&](const Body& b) {
    return pointNames(m, b) == Names{"J1", "J2", "J3"};
  });
  REQUIRE(plate != model->bodies.end());
  CHECK(plate->links.empty());
  CHECK(plate->name.rfind("body", 0) == 0);
}

TEST_CASE("bodiesOf: a PRP pin joins two blocks, one on a link and one on the ground", "[dynamics]") {
  const Mechanism m = linkwright::test::prpYoke();
  const auto model = bodiesOf(m);
  REQUIRE(model.ok());
  REQUIRE(model->bodies.size() == 4);
  CHECK(jointNames(*model) == Names{"O2", "C", "P:C_1", "P:C_2"});
  CHECK(model->prismatics[0].guide == BodyId{1});
  CHECK(model->prismatics[1].guide == kGroundBody);
  CHECK(model->findSlider({PointId{2}, 1}) == BodyId{3});
  CHECK_FALSE(model->findSlider({PointId{2}, 2}).has_value());
  CHECK(model->mobility() == 1);
}

TEST_CASE("linkLength reads each link's length from its definition", "[dynamics]") {
  const Mechanism shaperMech = makeShaper(kSeedShaper).value();
  CHECK(linkLength(shaperMech, shaper::kCrank) == 100.0);
  CHECK(linkLength(shaperMech, shaper::kRocker) == 400.0);
  CHECK(linkLength(shaperMech, shaper::kLink) == 150.0);
  const Mechanism s2 = makeStephensonIINewton().value();
  CHECK(linkLength(s2, stephenson2::kCoupler) == kStephensonIINewton.j1j2);
  CHECK(linkLength(s2, stephenson2::kLink5) == kStephensonIINewton.link5);
}

TEST_CASE("prismaticDirection: the slot of an RPR runs from its pivot to its tip", "[dynamics]") {
  const Mechanism m = makeShaper(kSeedShaper).value();
  const auto model = bodiesOf(m).value();
  const Pose pose = solvePose(m, {0.3, 1.0, 0.0}).value();
  const Eigen::Vector2d u = prismaticDirection(m, model.prismatics[0], pose);
  const Eigen::Vector2d expected = (pose.position[shaper::kD.index] - pose.position[shaper::kO4.index]).normalized();
  CHECK((u - expected).norm() < 1e-15);
  CHECK(prismaticDirection(m, model.prismatics[1], pose) == Eigen::Vector2d::UnitX());
}
