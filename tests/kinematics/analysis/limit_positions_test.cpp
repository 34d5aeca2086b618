// Tests kinematics/analysis/limit_positions.h: at each reported limit the rocker stops and the
// crank and coupler are in line; the crank angles, rocker swing and time ratio against the
// classic law-of-cosines construction; the swing against a fine sweep.

#include "kinematics/analysis/limit_positions.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::kAlvi;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {

// The classic construction for a crank-rocker on the Open branch (C above the frame line):
// at the limits O2C = b + a (extended) or b − a (folded), and the triangle O2–O4–C gives the
// angle ψ of O2C by the law of cosines. The crank points along O2C when extended and against
// it when folded.
struct Classic {
  double extendedCrank, foldedCrank, extendedRocker, foldedRocker;
};

Classic classic(const FourBarLengths& l) {
  const double a = l.crank, b = l.coupler, c = l.rocker, d = l.frame;
  const auto apex = [&](double rho) {
    const double psi = std::acos((rho * rho + d * d - c * c) / (2.0 * rho * d));
    return std::pair{psi, std::atan2(rho * std::sin(psi), rho * std::cos(psi) - d)};
  };
  const auto [psiExtended, rockerExtended] = apex(b + a);
  const auto [psiFolded, rockerFolded] = apex(b - a);
  return {psiExtended, psiFolded + kPi, rockerExtended, rockerFolded};
}

// At a reported limit: the rocker is at rest and the crank and coupler are in line.
void checkIsLimit(const FourBarLengths& l, Branch branch, const LimitPosition& p) {
  CAPTURE(radToDeg(p.crankAngle), p.extended);
  const Pose pose = linkwright::test::solveFourBar(l, branch, p.crankAngle, 1.0);
  const double t2 = pose.linkAngle[fourbar::kCrank.index];
  const double t3 = pose.linkAngle[fourbar::kCoupler.index];
  // ω4 ∝ sin(θ3 − θ2): round-off in the limit angle (~1e-15 rad) keeps both far below 1e-9.
  CHECK(std::abs(pose.linkOmega[fourbar::kRocker.index]) < 1e-9);
  CHECK(std::abs(std::sin(t3 - t2)) < 1e-9);
  CHECK((std::cos(t3 - t2) > 0.0) == p.extended);
  CHECK(angleDifference(pose.linkAngle[fourbar::kRocker.index], p.rockerAngle) == within(0.0, 1e-12));
  CHECK(p.crankAngle >= 0.0);
  CHECK(p.crankAngle < 2.0 * kPi);
}

}  // namespace

TEST_CASE("fourBarLimitPositions: crank-rockers match the classic construction", "[limit_positions]") {
  const auto [frame, crank, coupler, rocker] =
      GENERATE(table<double, double, double, double>({{60, 25, 70, 45}, {80, 20, 66, 56}}));
  const FourBarLengths l{frame, crank, coupler, rocker};
  CAPTURE(frame, crank, coupler, rocker);
  const Classic expected = classic(l);
  const LimitReport open = fourBarLimitPositions(l, Branch::Open);
  REQUIRE(open.positions.size() == 2);
  CHECK(open.positions[0].extended);
  CHECK_FALSE(open.positions[1].extended);
  // Exact closed forms on both sides, a few roundings through acos/atan2: 1e-12 rad.
  CHECK(open.positions[0].crankAngle == within(expected.extendedCrank, 1e-12));
  CHECK(open.positions[1].crankAngle == within(expected.foldedCrank, 1e-12));
  CHECK(open.positions[0].rockerAngle == within(expected.extendedRocker, 1e-12));
  CHECK(open.positions[1].rockerAngle == within(expected.foldedRocker, 1e-12));
  for (const LimitPosition& p : open.positions) checkIsLimit(l, Branch::Open, p);

  // Q = (180° + β)/(180° − β), β the difference of the two limit crank angles from 180°.
  const double beta = expected.foldedCrank - expected.extendedCrank - kPi;
  REQUIRE(open.timeRatio.has_value());
  CHECK(*open.timeRatio == within((kPi + beta) / (kPi - beta), 1e-12));
  CHECK(*open.timeRatio >= 1.0);
  CHECK(*open.slowStrokeCrankArc == within(kPi + std::abs(beta), 1e-12));
  CHECK(*open.slowStrokeCrankArc + *open.quickStrokeCrankArc == within(2.0 * kPi, 1e-12));
  CHECK(*open.rockerSwing == within(std::abs(expected.foldedRocker - expected.extendedRocker), 1e-12));

  // Crossed is the mirror image: crank angles 2π − θ, rocker angles negated, same ratio.
  const LimitReport crossed = fourBarLimitPositions(l, Branch::Crossed);
  REQUIRE(crossed.positions.size() == 2);
  for (const LimitPosition& p : crossed.positions) checkIsLimit(l, Branch::Crossed, p);
  CHECK(crossed.positions[0].crankAngle == within(2.0 * kPi - open.positions[1].crankAngle, 1e-12));
  CHECK(crossed.positions[1].crankAngle == within(2.0 * kPi - open.positions[0].crankAngle, 1e-12));
  CHECK(crossed.positions[0].rockerAngle == within(-open.positions[1].rockerAngle, 1e-12));
  REQUIRE(crossed.timeRatio.has_value());
  CHECK(*crossed.timeRatio == within(*open.timeRatio, 1e-12));
  CHECK(*crossed.rockerSwing == within(*open.rockerSwing, 1e-12));
}

TEST_CASE("fourBarLimitPositions: the thesis time ratio and swing", "[limit_positions]") {
  const LimitReport r = fourBarLimitPositions(kThesis, Branch::Open);
  // ψ = acos(10600/11400) = 21.5925° extended, acos(3600/5400) = 48.1897° folded, so
  // β = 26.5972° and Q = 206.5972/153.4028 = 1.34676 (values rounded to the digits shown).
  REQUIRE(r.timeRatio.has_value());
  CHECK(radToDeg(*r.slowStrokeCrankArc) == within(206.5972, 5e-5));
  CHECK(radToDeg(*r.quickStrokeCrankArc) == within(153.4028, 5e-5));
  CHECK(*r.timeRatio == within(1.34676, 5e-6));
}

TEST_CASE("The rocker swing equals the range of a fine sweep's rocker angle", "[limit_positions]") {
  for (const FourBarLengths& l : {kThesis, kAlvi}) {
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      CAPTURE(l.frame, branch == Branch::Open);
      const auto m = makeFourBar(l, branch);
      REQUIRE(m.ok());
      const std::size_t samples = 7201;
      const auto s = sweep(*m, {0.0, 2.0 * kPi, samples, 1.0, 0.0});
      REQUIRE(s.ok());
      const auto& rocker = s->linkAngle[fourbar::kRocker.index];
      const auto& alpha = s->linkAlpha[fourbar::kRocker.index];
      const auto [low, high] = std::minmax_element(rocker.begin(), rocker.end());
      const LimitReport r = fourBarLimitPositions(l, branch);
      REQUIRE(r.rockerSwing.has_value());
      // At an extreme θ4' = 0, so a sample within half a step s/2 of it misses by at most
      // ½·max|θ4''|·(s/2)²; with ω2 = 1 and α2 = 0, θ4'' is the rocker's α. Two extremes.
      const double step = 2.0 * kPi / static_cast<double>(samples - 1);
      double maxAlpha = 0.0;
      for (const double a : alpha) maxAlpha = std::max(maxAlpha, std::abs(a));
      const double sampling = 2.0 * 0.5 * maxAlpha * (step / 2.0) * (step / 2.0);
      const double sampled = *high - *low;
      CHECK(sampled <= *r.rockerSwing + 1e-12);
      CHECK(sampled >= *r.rockerSwing - sampling - 1e-12);
    }
  }
}

TEST_CASE("fourBarLimitPositions: linkages whose input does not turn fully have no time ratio", "[limit_positions]") {
  const auto [frame, crank, coupler, rocker, expectedCount] = GENERATE(table<double, double, double, double, int>({
      {25, 60, 45, 70, 0},   // double-crank: crank and coupler never line up
      {60, 50, 35, 40, -1},  // triple-rocker
      {50, 40, 80, 20, -1},  // triple-rocker about 180°
      {60, 45, 70, 25, -1},  // rocker-crank
      {60, 40, 20, 50, -1},  // double-rocker
  }));
  const FourBarLengths l{frame, crank, coupler, rocker};
  CAPTURE(frame, crank, coupler, rocker);
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const LimitReport r = fourBarLimitPositions(l, branch);
    if (expectedCount >= 0) CHECK(r.positions.size() == static_cast<std::size_t>(expectedCount));
    for (const LimitPosition& p : r.positions) checkIsLimit(l, branch, p);
    for (std::size_t i = 1; i < r.positions.size(); ++i)
      CHECK(r.positions[i - 1].crankAngle <= r.positions[i].crankAngle);
    CHECK_FALSE(r.timeRatio.has_value());
    CHECK_FALSE(r.rockerSwing.has_value());
  }
}
