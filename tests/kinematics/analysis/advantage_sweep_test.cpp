// The ratio columns against the two things they must agree with: the `centres` read-out at the
// same angle (mechanicalAdvantage of instantCentres of a solved pose) and the solver's own
// rates (ω4/ω2 from the sweep's link columns, v/ω2 for a slider, the same for a shaper's ram
// and a Watt II's second rocker). Samples that do not assemble are Undefined, a toggle is
// Infinite, no value is ever NaN or infinite, and a linkage without a crank is refused.

#include "kinematics/analysis/advantage_sweep.h"

#include "kinematics/analysis/quick_return.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/shaper.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

SweepResult sweepOf(const Mechanism& m, std::size_t samples) {
  const auto s = sweep(m, {0.0, 2.0 * kPi, samples, 2.5, 0.0});
  REQUIRE(s);
  return *s;
}

void checkFinite(const AdvantageSeries& series) {
  for (std::size_t j = 0; j < series.velocityRatio.size(); ++j) {
    CHECK(std::isfinite(series.velocityRatio[j].value));
    CHECK(std::isfinite(series.advantage[j].value));
    if (series.velocityRatio[j].kind != RatioKind::Finite) CHECK(series.velocityRatio[j].value == 0.0);
  }
}

}  // namespace

TEST_CASE("four-bar ratios equal the centres read-out and the solver's ω4/ω2", "[advantage_sweep]") {
  const Example ex = GENERATE(*findExample("thesis-crank-rocker"), *findExample("alvi-fourbar"));
  CAPTURE(ex.name);
  const SweepResult s = sweepOf(ex.mechanism, 73);
  const auto series = advantageSeries(ex.mechanism, s);
  REQUIRE(series);
  CHECK(series->bodies == RatioBodies{2, 4, false});
  checkFinite(*series);
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(radToDeg(s.inputAngle[j]));
    const auto pose = solvePose(ex.mechanism, {s.inputAngle[j], 0.0, 0.0}, SolveRequest{false, false});
    REQUIRE(pose);
    const MechanicalAdvantage ma = mechanicalAdvantage(instantCentres(ex.mechanism, *pose).value());
    CHECK(series->velocityRatio[j] == ma.velocityRatio);
    CHECK(series->advantage[j] == ma.advantage);
    // The solver's rates: 1e-9 of the ratio's size (centres are exact line intersections).
    REQUIRE(series->velocityRatio[j].kind == RatioKind::Finite);
    const double solver = s.linkOmega[fourbar::kRocker.index][j] / s.linkOmega[fourbar::kCrank.index][j];
    CHECK(std::abs(series->velocityRatio[j].value - solver) <= 1e-9 * std::max(1.0, std::abs(solver)));
    CHECK(std::abs(series->advantage[j].value * solver - 1.0) <= 1e-9);
  }
}

TEST_CASE("slider-crank ratios equal v/ω2 from the solver", "[advantage_sweep]") {
  const Example ex = *findExample("ls3-engine");
  const SweepResult s = sweepOf(ex.mechanism, 37);
  const auto series = advantageSeries(ex.mechanism, s);
  REQUIRE(series);
  CHECK(series->bodies == RatioBodies{2, 4, true});
  checkFinite(*series);
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(radToDeg(s.inputAngle[j]));
    const double v = s.velocity[slidercrank::kC.index][j].x() / 2.5;  // guide along +x, ω2 = 2.5 rad/s
    const Ratio& r = series->velocityRatio[j];
    REQUIRE(r.kind == RatioKind::Finite);
    CHECK(std::abs(r.value - v) <= 1e-9 * kLs3Engine.crank);
    // Dead centres (0° and 180°): the piston is at rest, the advantage infinite.
    if (std::abs(std::sin(s.inputAngle[j])) < 1e-12) CHECK(series->advantage[j].kind == RatioKind::Infinite);
  }
}

TEST_CASE("samples that do not assemble are undefined, a toggle is infinite", "[advantage_sweep]") {
  // Non-Grashof: the crank of 60/40/50/45 cannot pass the frame line's far side.
  const Mechanism m = makeFourBar({60.0, 40.0, 50.0, 45.0}, Branch::Open).value();
  const SweepResult s = sweepOf(m, 181);
  REQUIRE_FALSE(s.notAssembled.empty());
  const auto series = advantageSeries(m, s);
  REQUIRE(series);
  checkFinite(*series);
  for (std::size_t j = 0; j < s.size(); ++j)
    if (!s.assembled(j)) CHECK(series->velocityRatio[j].kind == RatioKind::Undefined);
  // Refused, naming why: a boom driven by a cylinder has no crank to compare with.
  const Mechanism boom = findExample("excavator-boom")->mechanism;
  const auto refused = advantageSeries(boom, sweep(boom, {1.2, 1.9, 5, 0.1, 0.0}).value());
  REQUIRE_FALSE(refused);
  CHECK(refused.error().code == ErrorCode::InvalidStructure);
  CHECK(refused.error().message.find("not driven by a crank turning about a frame pin") != std::string::npos);
  CHECK(ratioUnavailable(boom).has_value());
  CHECK_FALSE(ratioUnavailable(findExample("shaper")->mechanism).has_value());
}

TEST_CASE("a shaper's ratios are its ram's v/ω2, a Watt II's its second rocker's ω6/ω2", "[advantage_sweep]") {
  const Mechanism shaper = findExample("shaper")->mechanism;
  const SweepResult s = sweepOf(shaper, 73);
  const auto ram = advantageSeries(shaper, s);
  REQUIRE(ram);
  CHECK(ram->bodies == RatioBodies{2, 6, true});
  checkFinite(*ram);
  for (std::size_t j = 0; j < s.size(); ++j) {
    REQUIRE(ram->velocityRatio[j].kind == RatioKind::Finite);
    // The ram's guide runs along +x; ω2 = 2.5 rad/s.
    CHECK(ram->velocityRatio[j].value == Approx(s.velocity[shaper::kRam.index][j].x() / 2.5).margin(1e-9 * 400));
  }
  const Mechanism watt = findExample("watt-ii")->mechanism;
  const SweepResult w = sweepOf(watt, 73);
  const auto rocker = advantageSeries(watt, w);
  REQUIRE(rocker);
  CHECK(rocker->bodies == RatioBodies{2, 6, false});
  checkFinite(*rocker);
  const std::size_t last = watt.links.size() - 1;  // link6, the output rocker about O6
  for (std::size_t j = 0; j < w.size(); ++j)
    if (rocker->velocityRatio[j].kind == RatioKind::Finite)
      CHECK(rocker->velocityRatio[j].value == Approx(w.linkOmega[last][j] / 2.5).margin(1e-9));
}

TEST_CASE("the output comes to rest where its ratio passes through zero, not through a pole", "[advantage_sweep]") {
  // The LS3 (no offset) at its dead centres, 0° and 180°, which the grid holds exactly.
  const Mechanism ls3 = findExample("ls3-engine")->mechanism;
  const auto piston = advantageSeries(ls3, sweepOf(ls3, 73));
  REQUIRE(piston);
  CHECK(outputRests(*piston) == std::vector<OutputRest>{{0, 0.0}, {36, 0.0}, {72, 0.0}});
  // The shaper's ram reverses at the quick return's limits (the rocker's, crank ⟂ slot), read
  // off a 0.5° grid by linear interpolation.
  const auto example = findExample("shaper");
  const SweepResult s = sweepOf(example->mechanism, 721);
  const auto ram = advantageSeries(example->mechanism, s);
  REQUIRE(ram);
  const auto exact = shaperQuickReturn(asQuickReturn(example->mechanism)->geometry);
  REQUIRE(exact);
  const std::vector<OutputRest> rests = outputRests(*ram);
  REQUIRE(rests.size() == 2);
  std::vector<double> atDeg;
  for (const OutputRest& r : rests)
    atDeg.push_back(
        radToDeg(s.inputAngle[r.sample] + r.fraction * (s.inputAngle[r.sample + 1] - s.inputAngle[r.sample])));
  CHECK(atDeg[0] == Approx(radToDeg(exact->firstLimitCrankAngle)).margin(0.01));
  CHECK(atDeg[1] == Approx(radToDeg(exact->secondLimitCrankAngle)).margin(0.01));
  // Through zero the steps are smooth; through a pole the jump dwarfs its neighbours'.
  AdvantageSeries made;
  for (const double v : {0.3, 0.2, 0.1, -0.1, -0.2, 40.0, 400.0, -400.0, -40.0})
    made.velocityRatio.push_back({RatioKind::Finite, v});
  CHECK(outputRests(made) == std::vector<OutputRest>{{2, 0.5}});
}
