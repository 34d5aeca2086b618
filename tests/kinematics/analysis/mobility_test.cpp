// Tests kinematics/analysis/mobility.h: Gruebler's equation (thesis eq. (1)) for textbook
// cases, and the body and joint counts taken from a mechanism's structure.

#include "kinematics/analysis/mobility.h"
#include "kinematics/model/fourbar.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;

TEST_CASE("grueblerMobility: M = 3(N − 1) − 2jp − jh", "[mobility]") {
  const auto [links, full, half, expected] = GENERATE(table<int, int, int, int>({
      {4, 4, 0, 1},  // four-bar
      {5, 5, 0, 2},  // five-bar
      {3, 3, 0, 0},  // triangle: a structure
      {5, 6, 0, 0},  // five-bar with a diagonal: statically determinate truss
      {6, 7, 0, 1},  // Watt or Stephenson six-bar
      {3, 2, 1, 1},  // cam and follower: two pins and a cam contact
      {2, 1, 0, 1},  // a lone crank
      {1, 0, 0, 0},  // the ground alone
  }));
  CAPTURE(links, full, half);
  CHECK(grueblerMobility(links, full, half) == expected);
}

TEST_CASE("mobility counts the four-bar as N = 4, jp = 4, M = 1", "[mobility]") {
  const auto m = makeFourBar(linkwright::test::kThesis, Branch::Open);
  REQUIRE(m.ok());
  CHECK(mobility(*m) == MobilityReport{4, 4, 0, 1});
  // A point on the coupler adds neither a body nor a joint.
  const auto withPoint = makeFourBar(linkwright::test::kThesis, Branch::Open, "mm", CouplerPointSpec{10.0, 5.0});
  REQUIRE(withPoint.ok());
  CHECK(mobility(*withPoint) == MobilityReport{4, 4, 0, 1});
}

TEST_CASE("mobility counts a six-bar built from two dyads", "[mobility]") {
  const auto fourBar = makeFourBar(linkwright::test::kThesis, Branch::Open, "mm", CouplerPointSpec{30.0, 10.0});
  REQUIRE(fourBar.ok());
  Mechanism m = *fourBar;
  m.points.push_back({"O6", GroundPoint{Eigen::Vector2d(40.0, -50.0)}});
  m.points.push_back({"D", RrrPoint{fourbar::kCouplerPoint, 50.0, PointId{5}, 40.0, Branch::Crossed}});
  // Ground + crank + two dyads: N = 1 + 1 + 2 + 2 = 6, jp = 1 + 3 + 3 = 7.
  CHECK(mobility(m) == MobilityReport{6, 7, 0, 1});
}

TEST_CASE("mobility of a lone crank", "[mobility]") {
  Mechanism m;
  m.points = {{"O", GroundPoint{}}, {"A", CrankPoint{PointId{0}, 1.0, 0.0}}};
  m.links = {{"crank", PointId{0}, PointId{1}}};
  CHECK(mobility(m) == MobilityReport{2, 1, 0, 1});
}
