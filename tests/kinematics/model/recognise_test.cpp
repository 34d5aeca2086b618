// Tests kinematics/model/recognise.h: a four-bar or a quick return is recognised from its
// structure whichever way it was built (parents in either order, frame in any direction,
// crank with a phase, coupler points), and nothing else is taken for one.

#include "kinematics/model/recognise.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/sixbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {

// The thesis four-bar built point by point as a user might draw it: O4 first, the frame at
// 30°, C's parents as (O4, B), the crank with a 10° phase, a coupler point.
Mechanism drawnFourBar(Branch dyadBranch) {
  const double frameAngle = degToRad(30.0);
  Mechanism m;
  m.points = {{"O4", GroundPoint{Eigen::Vector2d(100.0, 50.0) +
                                 kThesis.frame * Eigen::Vector2d(std::cos(frameAngle), std::sin(frameAngle))}},
              {"O2", GroundPoint{Eigen::Vector2d(100.0, 50.0)}},
              {"B", CrankPoint{PointId{1}, kThesis.crank, degToRad(10.0)}},
              {"C", RrrPoint{PointId{0}, kThesis.rocker, PointId{2}, kThesis.coupler, dyadBranch}}};
  m.links = {
      {"crank", PointId{1}, PointId{2}}, {"rocker", PointId{0}, PointId{3}}, {"coupler", PointId{2}, PointId{3}}};
  m.points.push_back({"P", AttachedPoint{LinkId{2}, 20.0, 10.0}});
  return m;
}

}  // namespace

TEST_CASE("asFourBar reads makeFourBar's four-bars back exactly", "[recognise]") {
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const auto m = makeFourBar(kThesis, branch, "mm", CouplerPointSpec{35.0, -20.25});
    REQUIRE(m.ok());
    const auto s = asFourBar(*m);
    REQUIRE(s.has_value());
    CHECK(s->lengths == kThesis);
    CHECK(s->branch == branch);
    CHECK(s->o2 == fourbar::kO2);
    CHECK(s->o4 == fourbar::kO4);
    CHECK(s->b == fourbar::kB);
    CHECK(s->c == fourbar::kC);
    CHECK(s->frameAngle == 0.0);
    CHECK(s->crankPhase == 0.0);
    CHECK(s->inputAngle(1.25) == 1.25);
    CHECK_FALSE(asQuickReturn(*m).has_value());
  }
}

TEST_CASE("asFourBar recognises a four-bar drawn in any position, parents either way round", "[recognise]") {
  // C's parents are (O4, B): the dyad's open side (left of O4→B) is the four-bar's crossed one.
  const auto s = asFourBar(drawnFourBar(Branch::Open));
  REQUIRE(s.has_value());
  CHECK(s->branch == Branch::Crossed);
  CHECK(s->lengths.frame == within(kThesis.frame, 1e-12));
  CHECK(s->lengths.crank == kThesis.crank);
  CHECK(s->lengths.coupler == kThesis.coupler);
  CHECK(s->lengths.rocker == kThesis.rocker);
  CHECK(s->o2 == PointId{1});
  CHECK(s->o4 == PointId{0});
  CHECK(s->c == PointId{3});
  CHECK(s->frameAngle == within(degToRad(30.0), 1e-15));
  CHECK(s->crankPhase == within(degToRad(10.0), 1e-15));
  // A crank at 0° from the frame line is at 30° from +x, reached at an input angle of 20°.
  CHECK(s->inputAngle(0.0) == within(degToRad(20.0), 1e-15));
  CHECK(asFourBar(drawnFourBar(Branch::Crossed))->branch == Branch::Open);
}

TEST_CASE("asFourBar and asQuickReturn refuse what is not one", "[recognise]") {
  CHECK_FALSE(asFourBar(*makeSliderCrank(kLs3Engine)).has_value());
  CHECK_FALSE(asFourBar(*makeShaper(kSeedShaper)).has_value());
  CHECK_FALSE(asQuickReturn(*makeSliderCrank(kLs3Engine)).has_value());
  for (const SixBarGeometry& g : {kWattISixBar, kWattIISixBar, kStephensonISixBar}) {
    CHECK_FALSE(asFourBar(*makeSixBar(g)).has_value());
    CHECK_FALSE(asQuickReturn(*makeSixBar(g)).has_value());
  }
  // A point fixed on the rocker instead of the coupler makes it something else.
  Mechanism m = drawnFourBar(Branch::Open);
  std::get<AttachedPoint>(m.points.back().definition).link = LinkId{1};
  CHECK_FALSE(asFourBar(m).has_value());
}

TEST_CASE("asQuickReturn reads makeShaper's geometry and ram branch back", "[recognise]") {
  for (const ShaperGeometry& g : {kSeedShaper, kWhitworth})
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      const auto m = makeShaper(g, branch);
      REQUIRE(m.ok());
      const auto q = asQuickReturn(*m);
      REQUIRE(q.has_value());
      CHECK(q->geometry == g);
      CHECK(q->ramBranch == branch);
    }
}

TEST_CASE("a point on the rocker is allowed where PointsOnLinks::AnyLink says so", "[recognise]") {
  Mechanism m = drawnFourBar(Branch::Open);
  std::get<AttachedPoint>(m.points.back().definition).link = LinkId{1};  // on the rocker
  const auto s = asFourBar(m, PointsOnLinks::AnyLink);
  REQUIRE(s.has_value());
  CHECK(s->lengths == asFourBar(drawnFourBar(Branch::Open))->lengths);
  CHECK_FALSE(asSliderCrank(m, PointsOnLinks::AnyLink).has_value());
}

TEST_CASE("asSliderCrank reads makeSliderCrank's points and guide, and refuses the rest", "[recognise]") {
  for (const bool reversed : {false, true}) {
    const SliderCrankGeometry g{46.0, 150.0, 12.0, reversed};
    const auto s = asSliderCrank(makeSliderCrank(g).value());
    REQUIRE(s.has_value());
    CHECK(s->o2 == slidercrank::kO2);
    CHECK(s->b == slidercrank::kB);
    CHECK(s->c == slidercrank::kC);
    CHECK(std::cos(s->guideAngle) == within(reversed ? -1.0 : 1.0, 1e-15));
  }
  CHECK_FALSE(asSliderCrank(drawnFourBar(Branch::Open)).has_value());
  CHECK_FALSE(asSliderCrank(*makeShaper(kSeedShaper)).has_value());
  CHECK_FALSE(asSliderCrank(*makeSixBar(kWattIISixBar)).has_value());
  CHECK_FALSE(asFourBar(*makeSliderCrank(kLs3Engine)).has_value());
}
