// Tests kinematics/synthesis/freudenstein.h: the coefficients of the thesis four-bar (seed
// 000: frame 60, crank 25, coupler 70, rocker 45) in this repository's sign convention; the
// linkage recovered from three, and from eight, of its own positions solved by the pose
// solver; links that point the other way; degenerate point sets.

#include "kinematics/synthesis/freudenstein.h"

#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::solveFourBar;
using linkwright::test::within;

namespace {

// (θ2, θ4) of the thesis four-bar, open branch, as the solver gives them.
std::vector<AnglePair> thesisPairs(const std::vector<double>& crankDeg) {
  std::vector<AnglePair> pairs;
  for (const double deg : crankDeg) {
    const Pose pose = solveFourBar(kThesis, Branch::Open, degToRad(deg), 0.0);
    pairs.push_back({degToRad(deg), pose.linkAngle[fourbar::kRocker.index]});
  }
  return pairs;
}

}  // namespace

TEST_CASE("Freudenstein: the thesis four-bar's coefficients and its recovery from three positions",
          "[synthesis][freudenstein]") {
  // K1 = d/a = 60/25, K2 = d/c = 60/45, K3 = (a² − b² + c² + d²)/2ac = 1350/2250 = 0.6.
  const auto k = freudensteinCoefficients(thesisPairs({20.0, 110.0, 250.0}));
  REQUIRE(k.ok());
  // The solver's angles carry ~1e-15 rad; the 3×3 system is well conditioned here.
  CHECK(k->k1 == within(2.4, 1e-12));
  CHECK(k->k2 == within(60.0 / 45.0, 1e-12));
  CHECK(k->k3 == within(0.6, 1e-12));
  const auto l = freudensteinLinkage(*k, 60.0);
  REQUIRE(l.ok());
  CHECK(l->lengths.frame == 60.0);
  CHECK(l->lengths.crank == within(25.0, 1e-10));
  CHECK(l->lengths.coupler == within(70.0, 1e-10));
  CHECK(l->lengths.rocker == within(45.0, 1e-10));
  CHECK_FALSE(l->crankReversed);
  CHECK_FALSE(l->rockerReversed);
}

TEST_CASE("Freudenstein: least squares on eight exact positions recovers the linkage", "[synthesis][freudenstein]") {
  const auto pairs = thesisPairs({0.0, 40.0, 85.0, 130.0, 180.0, 220.0, 275.0, 330.0});
  const auto k = freudensteinCoefficients(pairs);
  REQUIRE(k.ok());
  CHECK(k->k1 == within(2.4, 1e-12));
  CHECK(k->k2 == within(60.0 / 45.0, 1e-12));
  CHECK(k->k3 == within(0.6, 1e-12));
  for (const AnglePair& p : pairs) CHECK(freudensteinResidual(*k, p) == within(0.0, 1e-13));
}

TEST_CASE("Freudenstein: a crank angle turned by π gives the reversed crank", "[synthesis][freudenstein]") {
  auto pairs = thesisPairs({20.0, 110.0, 250.0});
  for (AnglePair& p : pairs) p.input += kPi;
  const auto k = freudensteinCoefficients(pairs);
  REQUIRE(k.ok());
  CHECK(k->k1 == within(-2.4, 1e-12));
  const auto l = freudensteinLinkage(*k, 60.0);
  REQUIRE(l.ok());
  CHECK(l->crankReversed);
  CHECK_FALSE(l->rockerReversed);
  CHECK(l->lengths.crank == within(25.0, 1e-10));
  CHECK(l->lengths.coupler == within(70.0, 1e-10));
}

TEST_CASE("Freudenstein: too few or coincident positions are errors", "[synthesis][freudenstein][errors]") {
  const auto two = thesisPairs({20.0, 110.0});
  CHECK(freudensteinCoefficients(two).error().field == "points");
  auto same = thesisPairs({20.0, 110.0, 110.0});
  const auto k = freudensteinCoefficients(same);
  REQUIRE_FALSE(k.ok());
  CHECK(k.error().field == "points");
  std::vector<AnglePair> bad{{0.0, 1.0}, {NAN, 1.0}, {2.0, 0.5}};
  CHECK(freudensteinCoefficients(bad).error().field == "points");
  CHECK(freudensteinLinkage({0.0, 1.0, 0.5}, 1.0).error().field == "points");
  CHECK(freudensteinLinkage({2.4, 60.0 / 45.0, 0.6}, -1.0).error().field == "frame");
  // K3 so large that b² = a² + c² + d² − 2ac·K3 < 0: no real coupler.
  CHECK(freudensteinLinkage({2.4, 60.0 / 45.0, 100.0}, 60.0).error().field == "points");
}
