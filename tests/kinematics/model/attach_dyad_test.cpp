// Attaching dyads (attach_dyad.h), including sliders on moving guides (RRP) and two sliders
// pinned together (PRP): loops close, rates agree with finite differences, errors are named.

#include "kinematics/model/attach_dyad.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

Mechanism thesisFourBar() { return makeFourBar(linkwright::test::kThesis, Branch::Open).value(); }

// A slider S on the rocker (the guide along O4→C), pushed by a rod of 60 mm from a point P on
// the coupler: an RRP dyad whose guide turns with the rocker.
Mechanism sliderOnRocker() {
  Mechanism m = addPointOnLink(thesisFourBar(), "P", fourbar::kCoupler, 35.0, 20.0).value();
  return attachDyad(m, RrpDyadSpec{"S", PointId{4}, 60.0, Guide{fourbar::kRocker, {0.0, 0.0}, 0.0}, Branch::Open})
      .value();
}

// A pin Q in a vertical ground slot x = 30 and in a slot along the coupler, 10 mm off it: PRP.
Mechanism pinInTwoSlots() {
  return attachDyad(thesisFourBar(), PrpDyadSpec{"Q", Guide{std::nullopt, {30.0, 0.0}, kPi / 2.0},
                                                 Guide{fourbar::kCoupler, {0.0, 10.0}, 0.0}})
      .value();
}

}  // namespace

TEST_CASE("a slider on a moving guide stays on the guide at its rod's length", "[model][attach][rrp]") {
  const Mechanism m = sliderOnRocker();
  CHECK(mobility(m).mobility == 1);
  CHECK(m.links.back().name == "link5");
  const auto r = sweep(m, {0.0, 2.0 * kPi, 361, 1.0, 0.0});
  REQUIRE(r.ok());
  REQUIRE(r->notAssembled.empty());
  for (std::size_t j = 0; j < r->size(); ++j) {
    const Eigen::Vector2d o4 = r->position[fourbar::kO4.index][j];
    const Eigen::Vector2d c = r->position[fourbar::kC.index][j];
    const Eigen::Vector2d s = r->position[5][j];
    CHECK((s - r->position[4][j]).norm() == within(60.0, 1e-12));
    CHECK(cross((c - o4).normalized(), s - o4) == within(0.0, 1e-12));
  }
}

TEST_CASE("a slider on a moving guide: rates agree with finite differences", "[model][attach][rrp]") {
  const Mechanism m = sliderOnRocker();
  for (double deg = 0.0; deg < 360.0; deg += 37.0) {
    CAPTURE(deg);
    linkwright::test::checkAllRatesAgainstDifferences(m, {degToRad(deg), 3.0, 2.0}, 200.0);
  }
}

TEST_CASE("a pin in two slots is where the slots cross, and moves exactly", "[model][attach][prp]") {
  const Mechanism m = pinInTwoSlots();
  CHECK(mobility(m).mobility == 1);
  for (double deg = 0.0; deg < 360.0; deg += 29.0) {
    CAPTURE(deg);
    const auto pose = solvePose(m, {degToRad(deg), 2.0, 1.0});
    REQUIRE(pose.ok());
    const Eigen::Vector2d q = pose->position[4];
    const Eigen::Vector2d b = pose->position[fourbar::kB.index];
    const Eigen::Vector2d u = (pose->position[fourbar::kC.index] - b).normalized();
    CHECK(q.x() == within(30.0, 1e-12));
    CHECK(cross(u, q - b) == within(10.0, 1e-12));  // 10 mm to the left of the coupler line
    linkwright::test::checkAllRatesAgainstDifferences(m, {degToRad(deg), 2.0, 1.0}, 200.0);
  }
}

TEST_CASE("parallel guides cannot be assembled, and say so", "[model][attach][prp]") {
  const Mechanism m = attachDyad(thesisFourBar(), PrpDyadSpec{"Q", Guide{std::nullopt, {0.0, 0.0}, 0.0},
                                                              Guide{std::nullopt, {0.0, 5.0}, kPi}})
                          .value();
  const auto pose = solvePose(m, {0.3, 1.0, 0.0});
  REQUIRE_FALSE(pose.ok());
  CHECK(pose.error().code == ErrorCode::NotAssemblable);
  CHECK(pose.error().field == "Q");
  CHECK_THAT(pose.error().message, Catch::Contains("guides are parallel"));
}

TEST_CASE("attaching a dyad checks what it is given", "[model][attach]") {
  const Mechanism base = thesisFourBar();
  SECTION("a non-positive length") {
    const auto m = attachDyad(base, RrrDyadSpec{"E", fourbar::kC, -5.0, fourbar::kO4, 10.0, Branch::Open});
    REQUIRE_FALSE(m.ok());
    CHECK(m.error().field == "points[4].firstLength");
  }
  SECTION("a repeated name") {
    const auto m = attachDyad(base, RrrDyadSpec{"C", fourbar::kC, 5.0, fourbar::kO4, 10.0, Branch::Open});
    REQUIRE_FALSE(m.ok());
    CHECK_THAT(m.error().message, Catch::Contains("repeats the name 'C'"));
  }
  SECTION("a guide on a link that does not exist") {
    const auto m =
        attachDyad(base, RrpDyadSpec{"S", fourbar::kC, 5.0, Guide{LinkId{7}, {0.0, 0.0}, 0.0}, Branch::Open});
    REQUIRE_FALSE(m.ok());
    CHECK(m.error().field == "points[4].guide.link");
  }
  SECTION("a point on a link with a NaN offset") {
    const auto m = addPointOnLink(base, "P", fourbar::kRocker, std::nan(""), 0.0);
    REQUIRE_FALSE(m.ok());
    CHECK(m.error().field == "points[4].along");
  }
  CHECK(base == thesisFourBar());  // the input is untouched
}
