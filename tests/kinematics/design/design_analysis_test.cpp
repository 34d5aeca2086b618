// Tests kinematics/design/design_analysis.h: the analysis depends on what a linkage is, not on
// how it was stored. A four-bar drawn as a general linkage, in any position, gets the closed
// forms in input angles (checked against the solver: the range assembles and nothing outside
// it does; at each limit the crank and coupler are in line); a quick return is recognised
// without its kind; a lock between samples ends an assembled range.

#include "kinematics/design/design_analysis.h"
#include "kinematics/analysis/assembly_range.h"
#include "kinematics/design/derived_design.h"
#include "kinematics/design/design.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/parameters.h"
#include "kinematics/dynamics/spring_search.h"
#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"
#include "tests/support/locking_six_bar.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

// A triple rocker (60/50/35/40: the crank rocks within ±85.46° of the frame line) drawn with
// its frame at `frameDeg` and its crank's phase `phaseDeg`, C's parents as (O4, B).
Mechanism tripleRocker(double frameDeg, double phaseDeg) {
  const FourBarLengths l{60.0, 50.0, 35.0, 40.0};
  const Eigen::Vector2d o2(-30.0, 12.0);
  const double f = degToRad(frameDeg);
  Mechanism m;
  m.points = {{"O2", GroundPoint{o2}},
              {"O4", GroundPoint{o2 + l.frame * Eigen::Vector2d(std::cos(f), std::sin(f))}},
              {"B", CrankPoint{PointId{0}, l.crank, degToRad(phaseDeg)}},
              {"C", RrrPoint{PointId{1}, l.rocker, PointId{2}, l.coupler, Branch::Crossed}}};
  m.links = {
      {"crank", PointId{0}, PointId{2}}, {"rocker", PointId{1}, PointId{3}}, {"coupler", PointId{2}, PointId{3}}};
  return m;
}

}  // namespace

TEST_CASE("a four-bar analyses the same whether built as one or not", "[design][analysis]") {
  const Mechanism m = *makeFourBar(linkwright::test::kThesis, Branch::Crossed);
  const DesignAnalysis a = analyseDesign(m, SweepResult{});
  REQUIRE(a.grashof.has_value());
  CHECK(*a.grashof == classifyGrashof(linkwright::test::kThesis));
  CHECK(a.inputRange == fourBarInputRange(linkwright::test::kThesis));
  CHECK(a.transmission == fourBarTransmissionRange(linkwright::test::kThesis));
  CHECK(a.limits == fourBarLimitPositions(linkwright::test::kThesis, Branch::Crossed));
  CHECK_FALSE(a.quickReturn.has_value());
}

TEST_CASE("a four-bar in any position gets its exact range and limits in input angles", "[design][analysis]") {
  for (const double frameDeg : {0.0, 30.0, -135.0})
    for (const double phaseDeg : {0.0, 10.0}) {
      CAPTURE(frameDeg, phaseDeg);
      const Mechanism m = tripleRocker(frameDeg, phaseDeg);
      const DesignAnalysis a = analyseDesign(m, SweepResult{});
      REQUIRE(a.grashof.has_value());
      CHECK_FALSE(a.inputRange.fullRotation);
      REQUIRE(a.inputRange.ranges.size() == 1);
      const AngleRange r = a.inputRange.ranges[0];
      // Just inside the range the solver assembles; just outside it does not.
      for (const double edge : {r.from, r.to}) {
        const double inward = edge == r.from ? 1.0 : -1.0;
        CHECK(solvePose(m, {edge + inward * 1e-6, 0.0, 0.0}).ok());
        CHECK_FALSE(solvePose(m, {edge - inward * 1e-6, 0.0, 0.0}).ok());
      }
      // The transmission extremes at their input angles, in [0, 2π) like the limits.
      REQUIRE(a.transmission.has_value());
      for (const auto& [angle, mu] : {std::pair{a.transmission->minimumAtCrank, a.transmission->minimum},
                                      std::pair{a.transmission->maximumAtCrank, a.transmission->maximum}}) {
        CHECK(angle >= 0.0);
        CHECK(angle < 2.0 * kPi);
        const auto pose = solvePose(m, {angle, 0.0, 0.0}, {false, false});  // a toggle has no rates
        REQUIRE(pose.ok());
        CHECK(pose->transmissionAngle[3] == within(mu, 1e-6));  // √-steep next to a toggle
      }
      // At each limit position the coupler is in line with the crank, the rocker at the angle given.
      REQUIRE_FALSE(a.limits.positions.empty());
      for (const LimitPosition& p : a.limits.positions) {
        const auto pose = solvePose(m, {p.crankAngle, 0.0, 0.0}, {false, false});
        REQUIRE(pose.ok());
        const Eigen::Vector2d crank = pose->position[2] - pose->position[0];
        const Eigen::Vector2d coupler = pose->position[3] - pose->position[2];
        CHECK(std::abs(cross(crank.normalized(), coupler.normalized())) == within(0.0, 1e-6));
        const Eigen::Vector2d rocker = pose->position[3] - pose->position[1];
        CHECK(wrapAngle(std::atan2(rocker.y(), rocker.x()) - p.rockerAngle) == within(0.0, 1e-9));
      }
    }
}

TEST_CASE("a quick return is recognised from its structure, whatever its kind says", "[design][analysis]") {
  for (const ShaperGeometry& g : {kSeedShaper, kWhitworth}) {
    const DesignAnalysis a = analyseDesign(*makeShaper(g), SweepResult{});
    REQUIRE(a.quickReturn.has_value());
    CHECK(*a.quickReturn == *shaperQuickReturn(g, Branch::Open));
    CHECK_FALSE(a.grashof.has_value());
  }
}

TEST_CASE("assembledRange ends a range at a lock between two samples", "[design][analysis]") {
  const Mechanism m = *makeSixBar(linkwright::test::lockingSixBar());
  const auto sweep = linkwright::kinematics::sweep(m, {0.0, 2.0 * kPi, 73, 1.0, 0.0}, {false, false});
  REQUIRE(sweep.ok());
  const InputRange r = assembledRange(*sweep);
  CHECK_FALSE(r.fullRotation);
  REQUIRE(r.ranges.size() == 2);
  CHECK(radToDeg(r.ranges[0].to) == within(290.0, 1e-12));
  CHECK(radToDeg(r.ranges[1].from) == within(295.0, 1e-12));
}

TEST_CASE("a linear input's range holds only its own values: no turn wraps it", "[design][analysis]") {
  // The piston-driven slider-crank over 80 mm of its stroke: 0 mm and 2π mm are not in
  // [10, 70] mm, though 0 + 2π·k would be for a crank's angle.
  const Mechanism m = *makePistonDriven({40.0, 140.0, Branch::Open, "mm"});
  const auto sweep = linkwright::kinematics::sweep(m, {10.0, 70.0, 61, 1.0, 0.0}, {false, false});
  REQUIRE(sweep.ok());
  const InputRange r = assembledRange(*sweep, InputKind::Length);
  CHECK(r.period == 0.0);
  REQUIRE(r.ranges.size() == 1);
  CHECK_FALSE(r.contains(0.0));
  CHECK_FALSE(r.contains(2.0 * kPi));
  CHECK(r.contains(10.0));
  CHECK(r.clamp(0.0) == 10.0);
  CHECK(r.clamp(71.0) == 70.0);
  CHECK(r.clamp(33.0) == 33.0);
  // The same numbers as a crank's angles wrap: 2π·10 rad + 0.5 is 0.5 rad.
  const InputRange angles{false, {{0.0, 1.0}}};
  CHECK(angles.contains(20.0 * kPi + 0.5));
}

TEST_CASE("a linkage that assembles nowhere is refused in one sentence, a four-bar by its range",
          "[design][analysis][refusal]") {
  // Frame 60, crank 25, coupler 5, rocker 5: the coupler and rocker reach at most 10 of the 35
  // to 85 between the crank tip and the rocker pivot.
  const Mechanism stuck = *makeFourBar({60.0, 25.0, 5.0, 5.0}, Branch::Open);
  const auto e = assemblesNowhere(stuck, SweepResult{});
  REQUIRE(e);
  CHECK(e->code == ErrorCode::NotAssemblable);
  CHECK(e->field == "design");
  CHECK(e->message ==
        "This linkage cannot be assembled at any crank angle: the coupler and rocker cannot reach between the "
        "crank tip and the rocker pivot.");
  // The thesis four-bar turns fully; a non-Grashof one rocks: both assemble somewhere.
  CHECK_FALSE(assemblesNowhere(*makeFourBar(linkwright::test::kThesis, Branch::Open), SweepResult{}));
  CHECK_FALSE(assemblesNowhere(*makeFourBar({60.0, 25.0, 30.0, 45.0}, Branch::Open), SweepResult{}));
  // Any other linkage by its grid: the shaper assembles over its turn, and refused when no
  // sample did, with the sweep's first failure.
  const Design shaper = *designForExample("shaper");
  const auto grid = sweep(shaper.mechanism, designSweepSpec(shaper), {false, false});
  REQUIRE(grid);
  CHECK_FALSE(assemblesNowhere(shaper.mechanism, *grid));
  SweepResult none = *grid;
  for (PoseReport& r : none.report) r.status = PoseStatus::NotAssemblable;
  none.firstFailure = "D cannot be assembled at 0°";
  const auto refused = assemblesNowhere(shaper.mechanism, none);
  REQUIRE(refused);
  CHECK(refused->message == "This linkage cannot be assembled at any crank angle: D cannot be assembled at 0°.");
}

TEST_CASE("a spring balance's ends, points on the crank and the frame, leave a four-bar a four-bar",
          "[design_analysis][springs]") {
  // Edit ▸ Balance the torque by a spring added its ends as points to the mechanism, one on the
  // crank: the four-bar was then "6 points, 3 moving links", its Grashof class, time ratio and
  // rocker limits gone. A spring is a load; the linkage's kind and analysis are unchanged.
  const Design design = *designForExample("funsho-fourbar");
  const auto found = searchSpringBalance(design.mechanism, design.dynamics, designTurn(design), "crank");
  REQUIRE(found.ok());
  const Mechanism& sprung = found->mechanism;
  REQUIRE(sprung.points.size() == design.mechanism.points.size() + 2);
  const auto analyse = [](const Mechanism& m) {
    const auto grid = sweep(m, SweepSpec{0.0, 2.0 * kPi, 721, 1.0, 0.0});
    REQUIRE(grid.ok());
    return analyseDesign(m, *grid);
  };
  const DesignAnalysis before = analyse(design.mechanism), after = analyse(sprung);
  REQUIRE(before.grashof.has_value());
  REQUIRE(after.grashof.has_value());
  CHECK(after.grashof->category == before.grashof->category);
  REQUIRE(after.limits.timeRatio.has_value());
  CHECK(*after.limits.timeRatio == *before.limits.timeRatio);
  CHECK(after.limits.positions.size() == before.limits.positions.size());
  // The derived design keeps its four-bar, and its editors their named lengths.
  Design sprungDesign = design;
  sprungDesign.mechanism = sprung;
  const auto derived = deriveDesign(sprungDesign, NewtonSettings{});
  REQUIRE(derived.ok());
  REQUIRE(derived->fourBar.has_value());
  CHECK(derived->fourBar->lengths == asFourBar(design.mechanism)->lengths);
  const std::vector<Parameter> named = parametersOf(sprung);
  CHECK(std::count_if(named.begin(), named.end(), [](const Parameter& p) { return isFourBarDimension(p.slot); }) == 5);
  // Cognates still ask every point fixed on a link to be on the coupler.
  CHECK_FALSE(asFourBar(sprung).has_value());
}
