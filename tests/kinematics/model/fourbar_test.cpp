// Tests kinematics/model/fourbar.h (and the seed examples of design/examples.h): the built
// mechanism's layout, ids and lengths, and the length checks with their messages.

#include "kinematics/model/fourbar.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <limits>
#include <string>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;

TEST_CASE("makeFourBar lays out the thesis four-bar with the fixed ids", "[fourbar]") {
  const auto m = makeFourBar(kThesis, Branch::Open);
  REQUIRE(m.ok());
  CHECK_FALSE(checkMechanism(*m).has_value());
  CHECK(m->lengthUnit == "mm");
  REQUIRE(m->points.size() == 4);
  REQUIRE(m->links.size() == 3);

  CHECK(m->points[fourbar::kO2.index].name == "O2");
  CHECK(m->points[fourbar::kO4.index].name == "O4");
  CHECK(m->points[fourbar::kB.index].name == "B");
  CHECK(m->points[fourbar::kC.index].name == "C");
  CHECK(std::get<GroundPoint>(m->points[fourbar::kO2.index].definition).position == Eigen::Vector2d(0.0, 0.0));
  CHECK(std::get<GroundPoint>(m->points[fourbar::kO4.index].definition).position == Eigen::Vector2d(60.0, 0.0));

  const auto& crank = std::get<CrankPoint>(m->points[fourbar::kB.index].definition);
  CHECK(crank.pivot == fourbar::kO2);
  CHECK(crank.length == 25.0);
  CHECK(crank.phase == 0.0);

  const auto& dyad = std::get<RrrPoint>(m->points[fourbar::kC.index].definition);
  CHECK(dyad.first == fourbar::kB);
  CHECK(dyad.firstLength == 70.0);
  CHECK(dyad.second == fourbar::kO4);
  CHECK(dyad.secondLength == 45.0);
  CHECK(dyad.branch == Branch::Open);

  // Link directions fix the angle conventions: crank O2→B, coupler B→C, rocker O4→C.
  CHECK(m->links[fourbar::kCrank.index] == Link{"crank", fourbar::kO2, fourbar::kB});
  CHECK(m->links[fourbar::kCoupler.index] == Link{"coupler", fourbar::kB, fourbar::kC});
  CHECK(m->links[fourbar::kRocker.index] == Link{"rocker", fourbar::kO4, fourbar::kC});
  CHECK(m->findPoint("C") == fourbar::kC);
  CHECK(m->findLink("rocker") == fourbar::kRocker);
  CHECK_FALSE(m->findPoint("P").has_value());
}

TEST_CASE("makeFourBar keeps the branch, the unit and an optional coupler point", "[fourbar]") {
  const auto crossed = makeFourBar(kThesis, Branch::Crossed, "in");
  REQUIRE(crossed.ok());
  CHECK(crossed->lengthUnit == "in");
  CHECK(std::get<RrrPoint>(crossed->points[fourbar::kC.index].definition).branch == Branch::Crossed);

  const auto withPoint = makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{35.0, -12.5});
  REQUIRE(withPoint.ok());
  REQUIRE(withPoint->points.size() == 5);
  CHECK(withPoint->points[fourbar::kCouplerPoint.index].name == "P");
  const auto& p = std::get<AttachedPoint>(withPoint->points[fourbar::kCouplerPoint.index].definition);
  CHECK(p.link == fourbar::kCoupler);
  CHECK(p.along == 35.0);
  CHECK(p.across == -12.5);
  CHECK_FALSE(checkMechanism(*withPoint).has_value());
}

TEST_CASE("makeFourBar names the invalid length and its value", "[fourbar][errors]") {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto [field, value, shown] = GENERATE_COPY(table<std::string, double, std::string>({
      {"frame", 0.0, "0"},           {"frame", -60.0, "-60"},       {"frame", nan, "undefined"},
      {"frame", inf, "undefined"},   {"frame", -inf, "undefined"},  {"crank", 0.0, "0"},
      {"crank", -25.0, "-25"},       {"crank", nan, "undefined"},   {"crank", inf, "undefined"},
      {"crank", -inf, "undefined"},  {"coupler", 0.0, "0"},         {"coupler", -70.0, "-70"},
      {"coupler", nan, "undefined"}, {"coupler", inf, "undefined"}, {"coupler", -inf, "undefined"},
      {"rocker", 0.0, "0"},          {"rocker", -0.5, "-0.5"},      {"rocker", nan, "undefined"},
      {"rocker", inf, "undefined"},  {"rocker", -inf, "undefined"},
  }));
  CAPTURE(field, shown);
  FourBarLengths lengths = kThesis;
  if (field == "frame") lengths.frame = value;
  if (field == "crank") lengths.crank = value;
  if (field == "coupler") lengths.coupler = value;
  if (field == "rocker") lengths.rocker = value;

  const auto m = makeFourBar(lengths, Branch::Open);
  REQUIRE_FALSE(m.ok());
  CHECK(m.error().code == ErrorCode::InvalidValue);
  CHECK(m.error().field == field);
  CHECK(m.error().message == field + " length must be positive and finite (got " + shown + ")");
  const auto same = checkFourBarLengths(lengths);
  REQUIRE(same.has_value());
  CHECK(*same == m.error());
}

TEST_CASE("makeFourBar reports the first invalid length in frame, crank, coupler, rocker order", "[fourbar][errors]") {
  const auto m = makeFourBar({60.0, 25.0, -70.0, 0.0}, Branch::Open);
  REQUIRE_FALSE(m.ok());
  CHECK(m.error().field == "coupler");
  CHECK(m.error().message == "coupler length must be positive and finite (got -70)");
  CHECK_FALSE(checkFourBarLengths(kThesis).has_value());
}

TEST_CASE("makeFourBar rejects a non-finite coupler point", "[fourbar][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto along = makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{nan, 1.0});
  REQUIRE_FALSE(along.ok());
  CHECK(along.error().field == "coupler point along");
  CHECK(along.error().message == "coupler point along must be finite (got undefined)");
  const auto across =
      makeFourBar(kThesis, Branch::Open, "mm", CouplerPointSpec{1.0, std::numeric_limits<double>::infinity()});
  REQUIRE_FALSE(across.ok());
  CHECK(across.error().field == "coupler point across");
  CHECK(across.error().message == "coupler point across must be finite (got undefined)");
}

TEST_CASE("The built-in examples carry the seeds' data", "[fourbar][examples]") {
  const auto thesis = findExample("thesis-crank-rocker");
  REQUIRE(thesis.has_value());
  CHECK(thesis->kind == "four-bar");
  const auto thesisFourBar = asFourBar(thesis->mechanism);
  REQUIRE(thesisFourBar.has_value());
  CHECK(thesisFourBar->lengths == kThesis);
  CHECK(thesisFourBar->branch == Branch::Open);
  CHECK(thesis->omega == rpmToRadPerSec(10.0));
  CHECK(thesis->stepDeg == 30.0);

  const auto alvi = findExample("alvi-fourbar");
  REQUIRE(alvi.has_value());
  REQUIRE(asFourBar(alvi->mechanism).has_value());
  CHECK(asFourBar(alvi->mechanism)->lengths == linkwright::test::kAlvi);
  CHECK(alvi->omega == 10.5);
  CHECK(alvi->stepDeg == 40.0);

  CHECK_FALSE(findExample("no-such-example").has_value());
  // The seeds' four-bars come first, each makeFourBar's mechanism for its lengths.
  const std::vector<Example> all = examples();
  REQUIRE(all.size() >= 4);
  CHECK(all[0].name == "thesis-crank-rocker");
  CHECK(all[1].name == "alvi-fourbar");
  CHECK(all[2].name == "miranda-fourbar");
  CHECK(all[3].name == "funsho-fourbar");
  for (const Example& e : all) {
    if (e.kind != "four-bar") continue;
    CAPTURE(e.name);
    const auto s = asFourBar(e.mechanism);
    REQUIRE(s.has_value());
    const auto p = couplerPointOf(e.mechanism, *s);
    const auto built =
        makeFourBar(s->lengths, s->branch, e.mechanism.lengthUnit, p ? std::optional(p->spec) : std::nullopt);
    REQUIRE(built.ok());
    CHECK(*built == e.mechanism);
  }
}
