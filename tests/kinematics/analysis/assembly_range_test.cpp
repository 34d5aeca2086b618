// Tests kinematics/analysis/assembly_range.h: the exact crank-angle ranges of every shape
// (full turn, one range about 0°, one about 180°, two ranges, none) against the acos formula,
// and against the solver: just inside an edge assembles, just outside fails.

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <utility>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::within;

namespace {

// cos θ bounds of the loop-closure condition |b − c| ≤ BD ≤ b + c, computed here directly.
double farCos(const FourBarLengths& l) {
  return (l.crank * l.crank + l.frame * l.frame - std::pow(l.coupler + l.rocker, 2)) / (2.0 * l.crank * l.frame);
}
double nearCos(const FourBarLengths& l) {
  return (l.crank * l.crank + l.frame * l.frame - std::pow(l.coupler - l.rocker, 2)) / (2.0 * l.crank * l.frame);
}

bool assembles(const FourBarLengths& l, double angle) {
  const auto m = makeFourBar(l, Branch::Open);
  REQUIRE(m.ok());
  return solvePose(*m, {angle, 0.0, 0.0}, {false, false}).ok();
}

// Each edge of each range: 1e-7 rad inside assembles, the edge itself assembles (within
// kAssemblyTolerance), 1e-7 rad outside does not. 1e-7 rad moves BD by ~1e-6 mm here, far
// beyond the 1e-10 relative assembly slack, and far inside the next sample of any table.
void checkEdges(const FourBarLengths& l, const InputRange& range) {
  const auto m = makeFourBar(l, Branch::Open);
  REQUIRE(m.ok());
  for (const AngleRange& r : range.ranges) {
    for (const auto& [edge, inward] : {std::pair{r.from, 1.0}, std::pair{r.to, -1.0}}) {
      CAPTURE(radToDeg(edge));
      CHECK(assembles(l, edge + inward * 1e-7));
      CHECK(assembles(l, edge));
      CHECK_FALSE(assembles(l, edge - inward * 1e-7));
      const auto s = sweep(*m, {edge + inward * 1e-7, edge - inward * 1e-7, 3, 1.0, 0.0});
      REQUIRE(s.ok());
      CHECK(s->assembled(0));
      CHECK(s->assembled(1));
      CHECK_FALSE(s->assembled(2));
      REQUIRE(s->notAssembled.size() == 1);
      CHECK(s->notAssembled[0].from == s->inputAngle[2]);
    }
  }
}

}  // namespace

TEST_CASE("fourBarInputRange: the thesis crank turns fully", "[assembly_range]") {
  const InputRange r = fourBarInputRange(linkwright::test::kThesis);
  CHECK(r.fullRotation);
  CHECK(r.ranges == std::vector<AngleRange>{{0.0, 2.0 * kPi}});
  for (const double deg : {-720.0, -90.0, 0.0, 123.0, 359.9, 1000.0}) CHECK(r.contains(degToRad(deg)));
  CHECK(fourBarInputRange({25.0, 60.0, 45.0, 70.0}).fullRotation);  // double-crank
}

TEST_CASE("fourBarInputRange: one range about 0° equals ±acos of the far limit", "[assembly_range]") {
  const FourBarLengths l{60.0, 50.0, 35.0, 40.0};  // triple-rocker, BD ≤ b + c = 75 binds
  const double edge = std::acos(farCos(l));
  CHECK(farCos(l) == within(475.0 / 6000.0, 1e-16));
  const InputRange r = fourBarInputRange(l);
  CHECK_FALSE(r.fullRotation);
  REQUIRE(r.ranges.size() == 1);
  // Same few operations as the core's: agreement to an ulp or two.
  CHECK(r.ranges[0].from == within(-edge, 1e-15));
  CHECK(r.ranges[0].to == within(edge, 1e-15));
  checkEdges(l, r);
  CHECK(r.contains(0.0));
  CHECK(r.contains(2.0 * kPi - 0.5 * edge));  // the same range, one turn on
  CHECK(r.contains(edge + 1e-13));            // within the default 1e-12 tolerance
  CHECK_FALSE(r.contains(edge + 1e-11));
  CHECK_FALSE(r.contains(kPi));
}

TEST_CASE("fourBarInputRange: one range about 180° from the near limit", "[assembly_range]") {
  const FourBarLengths l{50.0, 40.0, 80.0, 20.0};  // triple-rocker, BD ≥ b − c = 60 binds
  const double edge = std::acos(nearCos(l));
  CHECK(nearCos(l) == within(0.125, 1e-16));
  const InputRange r = fourBarInputRange(l);
  REQUIRE(r.ranges.size() == 1);
  CHECK(r.ranges[0].from == within(edge, 1e-15));
  CHECK(r.ranges[0].to == within(2.0 * kPi - edge, 1e-14));
  checkEdges(l, r);
  CHECK(r.contains(kPi));
  CHECK(r.contains(-kPi));
  CHECK_FALSE(r.contains(0.0));
}

TEST_CASE("fourBarInputRange: two ranges when both limits bind", "[assembly_range]") {
  const auto [frame, crank, coupler, rocker] = GENERATE(table<double, double, double, double>({
      {60.0, 40.0, 20.0, 50.0},  // double-rocker
      {60.0, 45.0, 70.0, 25.0},  // rocker-crank: the input link rocks
  }));
  const FourBarLengths l{frame, crank, coupler, rocker};
  CAPTURE(frame, crank, coupler, rocker);
  const double nearEdge = std::acos(nearCos(l));
  const double farEdge = std::acos(farCos(l));
  const InputRange r = fourBarInputRange(l);
  REQUIRE(r.ranges.size() == 2);
  CHECK(r.ranges[0].from == within(nearEdge, 1e-15));
  CHECK(r.ranges[0].to == within(farEdge, 1e-15));
  CHECK(r.ranges[1].from == within(-farEdge, 1e-15));
  CHECK(r.ranges[1].to == within(-nearEdge, 1e-15));
  checkEdges(l, r);
  CHECK(r.contains(0.5 * (nearEdge + farEdge)));
  CHECK(r.contains(-0.5 * (nearEdge + farEdge)));
  CHECK_FALSE(r.contains(0.0));
  CHECK_FALSE(r.contains(kPi));
}

TEST_CASE("fourBarInputRange: a linkage that never closes", "[assembly_range]") {
  const InputRange r = fourBarInputRange({100.0, 1.0, 1.0, 1.0});
  CHECK_FALSE(r.fullRotation);
  CHECK(r.ranges.empty());
  CHECK_FALSE(r.contains(0.0));
  CHECK_FALSE(r.contains(kPi));
}

TEST_CASE("fourBarInputRange agrees with a fine sweep at every sample", "[assembly_range]") {
  const auto [frame, crank, coupler, rocker] =
      GENERATE(table<double, double, double, double>({{60.0, 25.0, 70.0, 45.0},
                                                      {60.0, 50.0, 35.0, 40.0},
                                                      {50.0, 40.0, 80.0, 20.0},
                                                      {60.0, 40.0, 20.0, 50.0},
                                                      {60.0, 45.0, 70.0, 25.0},
                                                      {100.0, 1.0, 1.0, 1.0}}));
  const FourBarLengths l{frame, crank, coupler, rocker};
  CAPTURE(frame, crank, coupler, rocker);
  const auto m = makeFourBar(l, Branch::Open);
  REQUIRE(m.ok());
  const auto s = sweep(*m, {-kPi, kPi, 3601, 1.0, 0.0}, {false, false});
  REQUIRE(s.ok());
  const InputRange r = fourBarInputRange(l);
  int checked = 0;
  for (std::size_t j = 0; j < s->size(); ++j) {
    const double angle = s->inputAngle[j];
    // Skip samples within 1e-9 rad of an edge, where the 1e-10 assembly slack decides.
    bool nearEdge = false;
    for (const AngleRange& e : r.ranges)
      nearEdge =
          nearEdge || std::abs(angleDifference(angle, e.from)) < 1e-9 || std::abs(angleDifference(angle, e.to)) < 1e-9;
    if (nearEdge) continue;
    CAPTURE(radToDeg(angle));
    CHECK(s->assembled(j) == r.contains(angle));
    ++checked;
  }
  CHECK(checked > 3590);
}

TEST_CASE("clamp keeps assemblable angles and stops others at the nearest edge", "[analysis][range]") {
  // Non-Grashof 40/30/20/25: |θ| ≤ 78.58°.
  const InputRange range = fourBarInputRange({40, 30, 20, 25});
  REQUIRE(range.ranges.size() == 1);
  const double edge = range.ranges[0].to;
  CHECK(range.clamp(0.5) == 0.5);
  CHECK(range.clamp(edge + 0.1) == edge);
  CHECK(range.clamp(-edge - 0.1) == -edge);
  CHECK(range.clamp(2.0 * kPi - edge - 0.2) == -edge);  // the same angle a turn later
  const InputRange full = fourBarInputRange({60, 25, 70, 45});
  CHECK(full.clamp(5.0) == 5.0);
}
