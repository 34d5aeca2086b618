// Tests kinematics/model/mechanism_check.h: every structural rule a mechanism must satisfy
// before the solvers may assume it, each broken on an otherwise valid four-bar, with the
// field and the message that name the culprit.

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/fourbar.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;

namespace {

Mechanism fourBarWithPoint() {
  auto m = makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{30.0, 10.0});
  REQUIRE(m.ok());
  return *m;
}

// Links are checked before points, so cases that break a point's references drop the links
// (and the coupler point that needs one) to reach the point rule they test.
void dropLinks(Mechanism& m) {
  m.points.resize(4);
  m.links.clear();
}

struct BrokenCase {
  std::string what;
  std::function<void(Mechanism&)> breakIt;
  ErrorCode code;
  std::string field;
  std::string message;
};

}  // namespace

TEST_CASE("checkMechanism accepts the four-bar and a six-bar built on it", "[mechanism_check]") {
  Mechanism m = fourBarWithPoint();
  CHECK_FALSE(checkMechanism(m).has_value());
  // A Watt-style six-bar: a second dyad hung from the coupler point P and a third pivot.
  m.points.push_back({"O6", GroundPoint{Eigen::Vector2d(40.0, -50.0)}});
  m.points.push_back({"D", RrrPoint{fourbar::kCouplerPoint, 50.0, PointId{5}, 40.0, Branch::Crossed}});
  m.links.push_back({"link5", fourbar::kCouplerPoint, PointId{6}});
  m.links.push_back({"link6", PointId{5}, PointId{6}});
  CHECK_FALSE(checkMechanism(m).has_value());
}

TEST_CASE("checkMechanism names the first structural or numeric problem", "[mechanism_check][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BrokenCase> cases{
      {"a point refers to a later point",
       [](Mechanism& m) {
         dropLinks(m);
         std::get<CrankPoint>(m.points[2].definition).pivot = PointId{3};
       },
       ErrorCode::InvalidStructure, "points[2].pivot",
       "points[2].pivot must refer to a point defined before it (got point 3)"},
      {"a dyad refers to itself",
       [](Mechanism& m) {
         dropLinks(m);
         std::get<RrrPoint>(m.points[3].definition).second = PointId{3};
       },
       ErrorCode::InvalidStructure, "points[3].second",
       "points[3].second must refer to a point defined before it (got point 3)"},
      {"no crank",
       [](Mechanism& m) {
         m.points.resize(2);  // the two pivots only: nothing drives it
         m.links.clear();
       },
       ErrorCode::InvalidStructure, "points",
       "points must contain exactly one driver: a crank, a point on a path or a linear actuator (got 0)"},
      {"two cranks",
       [](Mechanism& m) {
         m.points.push_back({"B2", CrankPoint{fourbar::kO4, 10.0, 0.0}});
       },
       ErrorCode::InvalidStructure, "points",
       "points must contain exactly one driver: a crank, a point on a path or a linear actuator (got 2)"},
      {"a crank pivot that is not on the ground",
       [](Mechanism& m) {
         m.points.push_back({"B2", CrankPoint{fourbar::kB, 10.0, 0.0}});
       },
       ErrorCode::InvalidStructure, "points[5].pivot", "points[5].pivot must be a ground point"},
      {"a link between points not held at a fixed distance",
       [](Mechanism& m) {
         m.links.push_back({"strut", fourbar::kO2, fourbar::kC});
       },
       ErrorCode::InvalidStructure, "links[3]", "links[3] joins points that are not held at a fixed distance"},
      {"a link to a point that does not exist",
       [](Mechanism& m) {
         m.links.push_back({"ghost", fourbar::kB, PointId{9}});
       },
       ErrorCode::InvalidStructure, "links[3]", "links[3] refers to a point that does not exist"},
      {"duplicate point names", [](Mechanism& m) { m.points[3].name = m.points[2].name; }, ErrorCode::InvalidStructure,
       "points[3].name", "points[3].name repeats the name 'B'"},
      {"an empty point name", [](Mechanism& m) { m.points[1].name.clear(); }, ErrorCode::InvalidStructure,
       "points[1].name", "points[1].name must not be empty"},
      {"an empty link name", [](Mechanism& m) { m.links[2].name.clear(); }, ErrorCode::InvalidStructure,
       "links[2].name", "links[2].name must not be empty"},
      {"a dyad whose two parents are the same point",
       [](Mechanism& m) {
         dropLinks(m);
         std::get<RrrPoint>(m.points[3].definition).second = fourbar::kB;
       },
       ErrorCode::InvalidStructure, "points[3].second", "points[3].second must differ from its first point"},
      {"a point on a link that does not exist",
       [](Mechanism& m) { std::get<AttachedPoint>(m.points[4].definition).link = LinkId{7}; },
       ErrorCode::InvalidStructure, "points[4].link", "points[4].link refers to a link that does not exist"},
      {"a point on a link to a later point",
       [](Mechanism& m) {
         m.points.push_back({"Q", AttachedPoint{LinkId{3}, 1.0, 0.0}});
         m.points.push_back({"B2", RrrPoint{fourbar::kO2, 30.0, fourbar::kO4, 40.0, Branch::Open}});
         m.links.push_back({"extra", fourbar::kO2, PointId{6}});
       },
       ErrorCode::InvalidStructure, "points[5].link", "points[5].link must be a link between points defined before it"},
      {"a negative dyad length", [](Mechanism& m) { std::get<RrrPoint>(m.points[3].definition).firstLength = -70.0; },
       ErrorCode::InvalidValue, "points[3].firstLength",
       "points[3].firstLength length must be positive and finite (got -70)"},
      {"a zero crank length", [](Mechanism& m) { std::get<CrankPoint>(m.points[2].definition).length = 0.0; },
       ErrorCode::InvalidValue, "points[2].length", "points[2].length length must be positive and finite (got 0)"},
      {"a NaN ground coordinate",
       [nan](Mechanism& m) { std::get<GroundPoint>(m.points[1].definition).position.y() = nan; },
       ErrorCode::InvalidValue, "points[1].y", "points[1].y must be finite (got undefined)"},
      {"an infinite crank phase",
       [](Mechanism& m) {
         std::get<CrankPoint>(m.points[2].definition).phase = std::numeric_limits<double>::infinity();
       },
       ErrorCode::InvalidValue, "points[2].phase", "points[2].phase must be finite (got undefined)"},
      {"a NaN offset on the coupler",
       [nan](Mechanism& m) { std::get<AttachedPoint>(m.points[4].definition).across = nan; }, ErrorCode::InvalidValue,
       "points[4].across", "points[4].across must be finite (got undefined)"},
  };
  for (const BrokenCase& c : cases) {
    DYNAMIC_SECTION(c.what) {
      Mechanism m = fourBarWithPoint();
      c.breakIt(m);
      const auto error = checkMechanism(m);
      REQUIRE(error.has_value());
      CHECK(error->code == c.code);
      CHECK(error->field == c.field);
      CHECK(error->message == c.message);
    }
  }
}

TEST_CASE("Mechanism lookups by name", "[mechanism_check]") {
  const Mechanism m = fourBarWithPoint();
  CHECK(m.findPoint("O2") == fourbar::kO2);
  CHECK(m.findPoint("P") == fourbar::kCouplerPoint);
  CHECK_FALSE(m.findPoint("p").has_value());
  CHECK(m.findLink("coupler") == fourbar::kCoupler);
  CHECK_FALSE(m.findLink("frame").has_value());
}
