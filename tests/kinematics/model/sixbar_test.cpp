// Dyad six-bars (sixbar.h): each example closes every loop over a full turn, has mobility 1,
// the Watt/Stephenson topology it claims, and exact rates that agree with finite differences.

#include "kinematics/model/sixbar.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <map>
#include <set>

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

const SixBarGeometry kAll[] = {kWattISixBar, kWattIISixBar, kStephensonISixBar, kStephensonIIISixBar};

// The rigid bodies and how many joints each carries: 2 binary, 3 ternary. Joints on the
// ground are the ground points; on a link, its two ends plus the points attached to it.
std::map<std::string, int> jointsPerBody(const Mechanism& m) {
  std::map<std::string, std::set<std::size_t>> joints;
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (std::holds_alternative<GroundPoint>(m.points[i].definition)) joints["ground"].insert(i);
  for (const Link& l : m.links) joints[l.name].insert({l.first.index, l.second.index});
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (const auto* a = std::get_if<AttachedPoint>(&m.points[i].definition))
      joints[m.links[a->link.index].name].insert(i);
  std::map<std::string, int> count;
  for (const auto& [body, set] : joints) count[body] = static_cast<int>(set.size());
  return count;
}

}  // namespace

TEST_CASE("six-bar examples assemble over the whole turn and close their loops", "[model][sixbar]") {
  for (const SixBarGeometry& g : kAll) {
    CAPTURE(sixBarKindName(g.kind));
    const auto m = makeSixBar(g);
    REQUIRE(m.ok());
    CHECK(mobility(*m).mobility == 1);
    CHECK(mobility(*m).links == 6);
    const auto r = sweep(*m, {0.0, 2.0 * kPi, 721, 2.0 * kPi, 3.0});
    REQUIRE(r.ok());
    CHECK(r->notAssembled.empty());
    CHECK(r->singularAngles.empty());
    const PointId p{4}, d{5}, e{6};
    for (std::size_t j = 0; j < r->size(); ++j) {
      CHECK((r->position[e.index][j] - r->position[p.index][j]).norm() == within(g.link5, 1e-12));
      CHECK((r->position[e.index][j] - r->position[d.index][j]).norm() == within(g.link6, 1e-12));
    }
  }
}

TEST_CASE("six-bar types have the ternary links their chain needs", "[model][sixbar]") {
  // Watt: the two ternary links are joined to each other; Stephenson: they are not.
  const auto watt1 = jointsPerBody(makeSixBar(kWattISixBar).value());
  CHECK(watt1.at("ground") == 2);
  CHECK(watt1.at("coupler") == 3);
  CHECK(watt1.at("rocker") == 3);  // coupler and rocker share C
  const auto watt2 = jointsPerBody(makeSixBar(kWattIISixBar).value());
  CHECK(watt2.at("ground") == 3);
  CHECK(watt2.at("rocker") == 3);  // ground and rocker share O4
  const auto steph1 = jointsPerBody(makeSixBar(kStephensonISixBar).value());
  CHECK(steph1.at("ground") == 2);
  CHECK(steph1.at("crank") == 3);
  CHECK(steph1.at("rocker") == 3);  // crank and rocker share no joint
  const auto steph3 = jointsPerBody(makeSixBar(kStephensonIIISixBar).value());
  CHECK(steph3.at("ground") == 3);
  CHECK(steph3.at("coupler") == 3);  // ground and coupler share no joint
  for (const auto* bodies : {&watt1, &watt2, &steph1, &steph3}) {
    int ternary = 0;
    for (const auto& [body, n] : *bodies) ternary += n == 3 ? 1 : 0;
    CHECK(ternary == 2);
    CHECK(bodies->size() == 6);
  }
}

TEST_CASE("six-bar rates agree with finite differences", "[model][sixbar]") {
  for (const SixBarGeometry& g : kAll) {
    CAPTURE(sixBarKindName(g.kind));
    const auto m = makeSixBar(g);
    REQUIRE(m.ok());
    for (double deg = 5.0; deg < 360.0; deg += 61.0) {
      CAPTURE(deg);
      linkwright::test::checkAllRatesAgainstDifferences(*m, {degToRad(deg), 6.0, -4.0}, 300.0);
    }
  }
}

TEST_CASE("six-bar geometry errors name the field", "[model][sixbar]") {
  SixBarGeometry g = kWattIISixBar;
  g.link5 = -1.0;
  CHECK(makeSixBar(g).error().field == "link5");
  g = kWattISixBar;
  g.second.across = std::nan("");
  CHECK(makeSixBar(g).error().field == "second.across");
  g = kStephensonIIISixBar;
  g.groundPivot.x() = INFINITY;
  CHECK(makeSixBar(g).error().field == "groundPivot.x");
  g.groundPivot.x() = 100.0;
  g.fourBar.coupler = 0.0;
  CHECK(makeSixBar(g).error().field == "coupler");
}
