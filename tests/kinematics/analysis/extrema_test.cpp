// Refined extremes: found between samples, they match the analytic or finely sampled extremes
// however coarse the sweep, and they never fall short of the best sample.

#include "kinematics/analysis/extrema.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/extrema.h"

#include "tests/support/catch.h"

#include <cmath>
#include <optional>
#include <random>
#include <utility>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::extremaOf;

TEST_CASE("the LS3 piston's peak speed is found exactly from only 12 samples", "[analysis][extrema]") {
  const auto m = makeSliderCrank({46.0, 6.098 * 25.4, 0.0, false});
  REQUIRE(m.ok());
  const double omega = 2.0 * kPi * 110.0;
  const PoseQuantity speed = [](const Pose& p, double) { return p.velocity[slidercrank::kC.index].x() / 1000.0; };
  const Extrema coarse = extremaOf(*m, {0.1, 0.1 + 2.0 * kPi, 13, omega, 0.0}, speed);
  const Extrema fine = extremaOf(*m, {0.0, 2.0 * kPi, 72001, omega, 0.0}, speed);
  // 72 001 samples bracket the peak to 5e-3°, where the speed is flat to ~1e-9 relative.
  CHECK(coarse.maximum.refined);
  CHECK(coarse.maximum.value == Approx(fine.maximum.value).epsilon(1e-9));
  CHECK(coarse.minimum.value == Approx(fine.minimum.value).epsilon(1e-9));
  CHECK(coarse.maximum.value == Approx(33.1744).epsilon(1e-5));  // independent closed-form sweep, 1e-3° steps
}

TEST_CASE("the piston's peak acceleration is rω²(1 + r/L) at top dead centre", "[analysis][extrema]") {
  const double r = 46.0, l = 154.8892, omega = 2.0 * kPi * 110.0;
  const auto m = makeSliderCrank({r, l, 0.0, false});
  REQUIRE(m.ok());
  const PoseQuantity accel = [](const Pose& p, double) { return p.acceleration[slidercrank::kC.index].x(); };
  const Extrema e = extremaOf(*m, {0.3, 0.3 + 2.0 * kPi, 25, omega, 0.0}, accel);
  CHECK(-e.minimum.value == Approx(r * omega * omega * (1.0 + r / l)).epsilon(1e-10));
  CHECK(std::remainder(e.minimum.inputAngle, 2.0 * kPi) == Approx(0.0).margin(1e-6));
}

TEST_CASE("refined extremes never fall short of the samples", "[analysis][extrema]") {
  const auto m = makeFourBar({60, 25, 70, 45}, Branch::Open);
  REQUIRE(m.ok());
  const PoseQuantity omega4 = [](const Pose& p, double) { return p.linkOmega[fourbar::kRocker.index]; };
  for (const std::size_t n : {7u, 13u, 37u, 361u}) {
    CAPTURE(n);
    const Extrema coarse = extremaOf(*m, {0.0, 2.0 * kPi, n, 1.0, 0.0}, omega4);
    const Extrema fine = extremaOf(*m, {0.0, 2.0 * kPi, 20001, 1.0, 0.0}, omega4);
    CHECK(coarse.maximum.value == Approx(fine.maximum.value).epsilon(1e-9));
    CHECK(coarse.minimum.value == Approx(fine.minimum.value).epsilon(1e-9));
  }
}

TEST_CASE("no valid sample gives no extrema", "[analysis][extrema]") {
  const auto m = makeFourBar({60, 25, 70, 45}, Branch::Open);
  REQUIRE(m.ok());
  const PoseQuantity q = [](const Pose&, double) { return 0.0; };
  CHECK_FALSE(refineExtrema(*m, {0.0, 1.0, 3, 1.0, 0.0}, {1.0, 2.0, 3.0}, {false, false, false}, q).has_value());
}

TEST_CASE("over a full turn an extremum just before the first sample is still found", "[analysis][extrema]") {
  // The thesis rocker's ω is lowest near 337°; shift the sweep so the first sample lies just past it.
  const auto m = makeFourBar({60, 25, 70, 45}, Branch::Open);
  REQUIRE(m.ok());
  const PoseQuantity omega4 = [](const Pose& p, double) { return p.linkOmega[fourbar::kRocker.index]; };
  const Extrema fine = extremaOf(*m, {0.0, 2.0 * kPi, 20001, 1.0, 0.0}, omega4);
  const double start = fine.minimum.inputAngle + 0.05;
  const Extrema shifted = extremaOf(*m, {start, start + 2.0 * kPi, 13, 1.0, 0.0}, omega4);
  CHECK(shifted.minimum.value == Approx(fine.minimum.value).epsilon(1e-9));
  CHECK(shifted.minimum.inputAngle >= start);
  CHECK(shifted.minimum.inputAngle <= start + 2.0 * kPi);
}

TEST_CASE("samples gathered one by one keep the best ones and their neighbours, as the whole column says",
          "[analysis][extrema][windows]") {
  std::mt19937 random(12);
  std::uniform_real_distribution<double> value(-5.0, 5.0);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 1 + random() % 40;
    std::vector<double> values(n);
    std::vector<bool> valid(n);
    SampledExtrema sampled;
    for (std::size_t j = 0; j < n; ++j) {
      valid[j] = random() % 4 != 0;
      // Few distinct values: ties, where the first of the best is kept.
      values[j] = valid[j] ? std::round(value(random)) : 0.0;
      sampled.add(j, valid[j], values[j]);
    }
    // The whole column, brute force.
    std::optional<std::size_t> lo, hi;
    for (std::size_t j = 0; j < n; ++j) {
      if (!valid[j]) continue;
      if (!lo || values[j] < values[*lo]) lo = j;
      if (!hi || values[j] > values[*hi]) hi = j;
    }
    CAPTURE(trial, n);
    REQUIRE(lo.has_value() == sampled.lowest().has_value());
    CHECK(sampled.samples() == n);
    if (n > 1) CHECK(sampled.secondValid() == valid[1]);
    if (n > 2) CHECK(sampled.lastButOneValid() == valid[n - 2]);
    if (!lo) continue;
    for (const auto& [best, index] : {std::pair{*sampled.lowest(), *lo}, std::pair{*sampled.highest(), *hi}}) {
      CHECK(best.index == index);
      CHECK(best.value == values[index]);
      CHECK(best.validBefore == (index > 0 && valid[index - 1]));
      CHECK(best.validAfter == (index + 1 < n && valid[index + 1]));
    }
  }
}
