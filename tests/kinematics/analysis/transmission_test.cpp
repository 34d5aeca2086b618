// Tests kinematics/analysis/transmission.h: the thesis's γ column, the exact extremes and
// where they occur, agreement with the pose solver, and that the exact extremes bound every
// sampled transmission angle of a fine sweep.

#include "kinematics/analysis/transmission.h"
#include "kinematics/analysis/assembly_range.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <utility>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::within;

TEST_CASE("fourBarTransmissionAngle reproduces the thesis γ column", "[transmission]") {
  // Thesis Table 5, γ in degrees, printed to two decimals.
  const auto [crankDeg, gammaDeg] = GENERATE(table<double, double>({{0, 25.21},
                                                                    {30, 32.76},
                                                                    {60, 48.19},
                                                                    {90, 64.62},
                                                                    {120, 79.02},
                                                                    {150, 89.07},
                                                                    {180, 92.73},
                                                                    {210, 89.07},
                                                                    {240, 79.02},
                                                                    {270, 64.62},
                                                                    {300, 48.19},
                                                                    {330, 32.76},
                                                                    {360, 25.21}}));
  CAPTURE(crankDeg);
  const auto mu = fourBarTransmissionAngle(kThesis, degToRad(crankDeg));
  REQUIRE(mu.has_value());
  CHECK(radToDeg(*mu) == within(gammaDeg, 0.005 + 1e-9));  // the thesis prints two decimals
  // The pose solver measures the same angle at C.
  const Pose pose = linkwright::test::solveFourBar(kThesis, Branch::Open, degToRad(crankDeg), 1.0);
  CHECK(pose.transmissionAngle[fourbar::kC.index] == within(*mu, 1e-12));
}

TEST_CASE("fourBarTransmissionRange: thesis min 25.21° at 0°, max 92.73° at 180°", "[transmission]") {
  const auto r = fourBarTransmissionRange(kThesis);
  REQUIRE(r.has_value());
  CHECK(radToDeg(r->minimum) == within(25.21, 0.005));  // the thesis prints two decimals
  CHECK(radToDeg(r->maximum) == within(92.73, 0.005));
  // Exact: BD = 35 and 85 in cos μ = (b² + c² − BD²)/2bc; acos of simple ratios to 1e-15.
  CHECK(r->minimum == within(std::acos(5700.0 / 6300.0), 1e-15));
  CHECK(r->maximum == within(std::acos(-300.0 / 6300.0), 1e-15));
  CHECK(r->minimumAtCrank == within(0.0, 1e-15));
  CHECK(r->maximumAtCrank == within(kPi, 1e-15));
  CHECK(r->worstDeviation == within(kPi / 2.0 - r->minimum, 1e-15));
}

TEST_CASE("fourBarTransmissionRange: toggles at the edges of a limited range", "[transmission]") {
  SECTION("triple-rocker 60/50/35/40: μ reaches 180° where BD = b + c") {
    const FourBarLengths l{60.0, 50.0, 35.0, 40.0};
    const auto r = fourBarTransmissionRange(l);
    REQUIRE(r.has_value());
    // Here cos μ = (35² + 40² − 75²)/2800 = −1 exactly: μ = π to the last bit or two.
    CHECK(r->maximum == within(kPi, 1e-15));
    CHECK(r->maximumAtCrank == within(fourBarInputRange(l).ranges[0].to, 1e-15));
    CHECK(r->minimum == within(std::acos(2725.0 / 2800.0), 1e-15));  // BD = 10 at θ = 0
    CHECK(r->minimumAtCrank == within(0.0, 1e-15));
    CHECK(r->worstDeviation == within(kPi / 2.0, 1e-15));
  }
  SECTION("double-rocker 60/40/20/50: μ spans 0° to 180°") {
    const auto r = fourBarTransmissionRange({60.0, 40.0, 20.0, 50.0});
    REQUIRE(r.has_value());
    // cos μ = ±1 exactly at BD = |b − c| = 30 and b + c = 70.
    CHECK(r->minimum == within(0.0, 1e-15));
    CHECK(r->maximum == within(kPi, 1e-15));
    CHECK(r->minimumAtCrank == within(std::acos(4300.0 / 4800.0), 1e-15));  // BD = 30
    CHECK(r->maximumAtCrank == within(std::acos(300.0 / 4800.0), 1e-15));   // BD = 70
  }
  SECTION("never assembles") {
    CHECK_FALSE(fourBarTransmissionRange({100.0, 1.0, 1.0, 1.0}).has_value());
    CHECK_FALSE(fourBarTransmissionAngle({100.0, 1.0, 1.0, 1.0}, 0.0).has_value());
  }
  SECTION("outside the assemblable range there is no angle") {
    CHECK_FALSE(fourBarTransmissionAngle({60.0, 50.0, 35.0, 40.0}, kPi).has_value());
    CHECK(fourBarTransmissionAngle({60.0, 50.0, 35.0, 40.0}, 0.0).has_value());
  }
}

TEST_CASE("The exact extremes bound a fine sweep's transmission angles", "[transmission]") {
  const auto [frame, crank, coupler, rocker] =
      GENERATE(table<double, double, double, double>({{60.0, 25.0, 70.0, 45.0},
                                                      {80.0, 20.0, 66.0, 56.0},
                                                      {25.0, 60.0, 45.0, 70.0},
                                                      {60.0, 50.0, 35.0, 40.0},
                                                      {60.0, 45.0, 70.0, 25.0}}));
  const FourBarLengths l{frame, crank, coupler, rocker};
  CAPTURE(frame, crank, coupler, rocker);
  const auto m = makeFourBar(l, Branch::Open);
  REQUIRE(m.ok());
  // A grid offset from 0° and 180°, so no sample sits on an extreme by construction.
  const auto s = sweep(*m, {0.001, 0.001 + 2.0 * kPi, 2001, 1.0, 0.0}, {false, false});
  REQUIRE(s.ok());
  const auto exact = fourBarTransmissionRange(l);
  REQUIRE(exact.has_value());
  const auto& mu = s->transmissionAngle[fourbar::kC.index];
  double low = kPi, high = 0.0, largestStep = 0.0;
  for (std::size_t j = 0; j < s->size(); ++j) {
    if (!s->assembled(j)) continue;
    CAPTURE(radToDeg(s->inputAngle[j]));
    // Exact and sampled values both carry ~1e-15 rad of round-off (√ε ≈ 1.5e-8 at 0° and
    // 180°, where acos is ill-conditioned).
    CHECK(mu[j] >= exact->minimum - 2e-8);
    CHECK(mu[j] <= exact->maximum + 2e-8);
    low = std::min(low, mu[j]);
    high = std::max(high, mu[j]);
    if (j > 0 && s->assembled(j - 1)) largestStep = std::max(largestStep, std::abs(mu[j] - mu[j - 1]));
  }
  // With a full turn the extremes lie inside the grid (θ = 0°, 180°), within half a step of a
  // sample, so the sampled extreme misses by at most the largest change between neighbours.
  // (At the edge of a limited range μ has a square-root cusp and no such bound holds.)
  if (fourBarInputRange(l).fullRotation) {
    CHECK(low == within(exact->minimum, largestStep + 2e-8));
    CHECK(high == within(exact->maximum, largestStep + 2e-8));
  }
  // The extremes are attained where the analysis says. At a toggle μ comes from h ≈ √(round-off)
  // there, so it is 0 or π only to about √ε·(a few): 1e-7.
  for (const auto& [angle, value] :
       {std::pair{exact->minimumAtCrank, exact->minimum}, std::pair{exact->maximumAtCrank, exact->maximum}}) {
    const auto pose = solvePose(*m, {angle, 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    CHECK(pose->transmissionAngle[fourbar::kC.index] == within(value, 1e-7));
  }
}

TEST_CASE("worstTransmissionBetween is the worst of a fine sampling over the span, and no better", "[transmission]") {
  // The thesis crank-rocker over spans that do and do not hold θ = 0 or π.
  const auto [fromDeg, toDeg] =
      GENERATE(table<double, double>({{20, 70}, {-30, 40}, {100, 260}, {250, 20}, {-400, -10}}));
  CAPTURE(fromDeg, toDeg);
  const double from = degToRad(fromDeg), to = degToRad(toDeg);
  const auto worst = worstTransmissionBetween(kThesis, from, to);
  REQUIRE(worst.has_value());
  double sampled = kPi / 2.0;
  for (int i = 0; i <= 20000; ++i) {
    const double mu = fourBarTransmissionAngle(kThesis, from + (to - from) * i / 20000.0).value();
    sampled = std::min(sampled, std::min(mu, kPi - mu));
  }
  CHECK(*worst <= sampled + 1e-12);
  CHECK(*worst >= sampled - 1e-6);
}

TEST_CASE("worstTransmissionBetween: nullopt where an end cannot be assembled", "[transmission]") {
  // Frame 80, crank 60, coupler and rocker 30: at θ = 3 rad B is 140 from O4, beyond their 60.
  const FourBarLengths l{80.0, 60.0, 30.0, 30.0};
  CHECK_FALSE(worstTransmissionBetween(l, 0.5, 3.0).has_value());
}
