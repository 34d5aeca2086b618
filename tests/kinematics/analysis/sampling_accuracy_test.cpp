// Peaks read off samples against exact refined peaks (sampling_accuracy.h): the exact peaks
// match closed forms, reading errors shrink as the sampling is refined, and the Newton
// tolerance a request sets is the accuracy it gets.

#include "kinematics/analysis/sampling_accuracy.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/constraint_form.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("exact peaks of the LS3 piston match its closed form", "[accuracy]") {
  // The piston's largest acceleration is at top dead centre, r·ω²·(1 + r/L), exactly.
  const Mechanism m = makeSliderCrank(kLs3Engine).value();
  const double w = 2.0 * kPi * 110.0, r = kLs3Engine.crank, l = kLs3Engine.rod;
  const auto peaks = exactPeaks(m, w);
  REQUIRE(peaks.ok());
  CHECK(peaks->pointAcceleration[slidercrank::kC.index] == Approx(r * w * w * (1.0 + r / l)).epsilon(1e-12));
  CHECK(peaks->pointSpeed[slidercrank::kB.index] == Approx(r * w).epsilon(1e-12));
  // 33174.4272 mm/s as the extremes command prints it (4 decimals), checked there on 72 001 samples.
  CHECK(peaks->pointSpeed[slidercrank::kC.index] == Approx(33174.4272).epsilon(0).margin(5e-5));
  CHECK(peaks->linkOmega[slidercrank::kCrank.index] == 0.0);  // the driven crank is not measured
  CHECK(peaks->linkRocks[slidercrank::kRod.index]);
}

TEST_CASE("peaks read off samples converge to the exact ones", "[accuracy]") {
  const auto e = findExample("miranda-fourbar").value();
  const FourBarStructure s = asFourBar(e.mechanism).value();
  const Mechanism m = makeFourBar(s.lengths, s.branch, "mm", couplerPointOf(e.mechanism, s).value().spec).value();
  REQUIRE(m == e.mechanism);
  const auto exact = exactPeaks(m, e.omega, 3600);
  REQUIRE(exact.ok());
  double previous = 1.0;
  for (const std::size_t n : {36u, 360u, 3600u}) {
    CAPTURE(n);
    const auto read = sampledPeaks(m, e.omega, n, DerivativeMethod::Exact);
    const auto frames = sampledPeaks(m, e.omega, n, DerivativeMethod::FiniteDifference);
    REQUIRE(read.ok());
    REQUIRE(frames.ok());
    const double error = peakError(*read, *exact).worstRate();
    // A sampled peak misses by ~(Δθ)²·curvature: ten times the samples, ~100 times smaller.
    CHECK(error < previous / 20.0);
    CHECK(error > 0.0);
    // Differencing adds its own O(Δθ²) error on top of the sampling's.
    CHECK(peakError(*frames, *exact).worstRate() >= 0.5 * error);
    previous = error;
  }
  // Refined from only 36 samples, the peaks agree with those refined from 3600 to round-off.
  const auto refined = exactPeaks(m, e.omega, 36);
  REQUIRE(refined.ok());
  CHECK(peakError(*refined, *exact).worstRate() < 1e-12);
  CHECK(peakError(*refined, *exact).angle < 1e-12);
}

TEST_CASE("a sweep's Newton tolerance is the accuracy it delivers", "[accuracy][newton]") {
  const auto e = findExample("miranda-fourbar").value();
  const FourBarStructure s = asFourBar(e.mechanism).value();
  const Mechanism m = makeFourBar(s.lengths, s.branch, "mm").value();
  const auto start = solvePose(m, {0.0, e.omega, 0.0}, {false, false});
  REQUIRE(start.ok());
  const Mechanism newton = withNewtonPoints(m, start->position);
  const auto closed = sampledPeaks(m, e.omega, 360, DerivativeMethod::Exact);
  REQUIRE(closed.ok());
  const auto loose = sampledPeaks(newton, e.omega, 360, DerivativeMethod::Exact, {1e-4, 50});
  const auto tight = sampledPeaks(newton, e.omega, 360, DerivativeMethod::Exact, {1e-12, 50});
  REQUIRE(loose.ok());
  REQUIRE(tight.ok());
  // 1e-4 of a 250 mm linkage leaves misfits up to 0.025 mm: visible in the peaks.
  CHECK(peakError(*loose, *closed).worstRate() > 1e-7);
  CHECK(peakError(*tight, *closed).worstRate() < 1e-10);
}

TEST_CASE("peak measurement refuses what it cannot measure", "[accuracy][errors]") {
  const Mechanism rocking = makeFourBar({40.0, 30.0, 20.0, 25.0}, Branch::Open).value();  // non-Grashof
  const auto peaks = exactPeaks(rocking, 1.0);
  REQUIRE_FALSE(peaks.ok());
  CHECK_THAT(peaks.error().message, Catch::Contains("the crank must turn fully"));
  const Mechanism m = makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value();
  CHECK(sampledPeaks(m, 1.0, 2, DerivativeMethod::Exact).error().field == "samples");
  CHECK(exactPeaks(m, -1.0).error().field == "omega");
}
