// Tests kinematics/synthesis/defects.h on linkages whose behaviour is known independently:
// the thesis crank-rocker (60, 25, 70, 45) turns fully; the triple-rocker (60, 50, 35, 40)
// rocks within the range fourBarInputRange gives. Order, branch, Grashof, transmission and
// link-length defects each appear exactly when they should, with a message.

#include "kinematics/synthesis/defects.h"

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/transmission.h"
#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {

constexpr FourBarLengths kTripleRocker{60.0, 50.0, 35.0, 40.0};

std::vector<double> degrees(std::initializer_list<double> values) {
  std::vector<double> out;
  for (const double v : values) out.push_back(degToRad(v));
  return out;
}

bool has(const FourBarCheck& c, DefectKind kind) {
  return std::any_of(c.defects.begin(), c.defects.end(), [&](const Defect& d) { return d.kind == kind; });
}

DefectBounds noBounds() { return {0.0, std::nullopt, std::nullopt}; }

}  // namespace

TEST_CASE("Order defect: a fully turning crank meets four positions out of order", "[synthesis][defects]") {
  const std::vector<Branch> open(4, Branch::Open);
  const auto inOrder = checkFourBar({kThesis, degrees({0, 90, 180, 270}), open}, noBounds());
  CHECK(inOrder.defects.empty());
  const auto clockwise = checkFourBar({kThesis, degrees({0, 270, 180, 90}), open}, noBounds());
  CHECK(clockwise.defects.empty());
  const auto mixed = checkFourBar({kThesis, degrees({0, 90, 45, 180}), open}, noBounds());
  REQUIRE(has(mixed, DefectKind::Order));
  CHECK(mixed.defects.front().message.find("1, 3, 2, 4") != std::string::npos);
  // Three positions are always in order one way round.
  CHECK(checkFourBar({kThesis, degrees({0, 200, 100}), {3, Branch::Open}}, noBounds()).defects.empty());
}

TEST_CASE("A rocking crank: order within its range, and positions outside it", "[synthesis][defects]") {
  const InputRange range = fourBarInputRange(kTripleRocker);
  REQUIRE_FALSE(range.fullRotation);
  REQUIRE_FALSE(range.ranges.empty());
  const AngleRange r = range.ranges.front();
  const auto at = [&](double f) { return r.from + f * (r.to - r.from); };
  const std::vector<Branch> open(3, Branch::Open);
  CHECK(checkFourBar({kTripleRocker, {at(0.2), at(0.4), at(0.6)}, open}, noBounds()).defects.empty());
  CHECK(checkFourBar({kTripleRocker, {at(0.6), at(0.4), at(0.2)}, open}, noBounds()).defects.empty());
  const auto swapped = checkFourBar({kTripleRocker, {at(0.2), at(0.6), at(0.4)}, open}, noBounds());
  CHECK(has(swapped, DefectKind::Order));
  // Half a turn from the middle of the range is outside every range the crank can reach.
  const double outside = 0.5 * (r.from + r.to) + kPi;
  REQUIRE_FALSE(range.contains(outside));
  const auto apart = checkFourBar({kTripleRocker, {at(0.2), outside, at(0.6)}, open}, noBounds());
  CHECK(has(apart, DefectKind::Branch));
}

TEST_CASE("Grashof and branch defects", "[synthesis][defects]") {
  const auto rocking = checkFourBar({kTripleRocker, {}, {}, true}, noBounds());
  CHECK(has(rocking, DefectKind::NotGrashof));
  CHECK(rocking.grashof.category == GrashofClass::TripleRocker);
  CHECK_FALSE(has(checkFourBar({kThesis, {}, {}, true}, noBounds()), DefectKind::NotGrashof));
  const auto split = checkFourBar({kThesis, degrees({0, 90}), {Branch::Open, Branch::Crossed}}, noBounds());
  REQUIRE(has(split, DefectKind::Branch));
  CHECK(split.defects.front().message.find("crossed") != std::string::npos);
}

TEST_CASE("Transmission over a working range is exact", "[synthesis][defects]") {
  // The worst transmission over 30°..150° against a 0.01° scan of the exact angle.
  const CrankSpan span{degToRad(30.0), degToRad(150.0)};
  const auto worst = worstTransmissionOver(kThesis, span);
  REQUIRE(worst.has_value());
  double scanned = kPi / 2.0;
  for (int k = 0; k <= 12000; ++k) {
    const auto mu = fourBarTransmissionAngle(kThesis, span.from + (span.to - span.from) * k / 12000.0);
    REQUIRE(mu.has_value());
    scanned = std::min(scanned, std::min(*mu, kPi - *mu));
  }
  CHECK(*worst == within(scanned, 1e-12));  // the extreme is at an end, which the scan hits
  // Over the full turn it is the thesis's 25.21° at θ = 0 (transmission_test.cpp).
  CHECK(radToDeg(*worstTransmission(kThesis)) == within(25.21, 5e-3));
  const auto full = checkFourBar({kThesis}, DefectBounds{});
  CHECK(has(full, DefectKind::Transmission));
  CHECK(full.minTransmission == within(*worstTransmission(kThesis), 0.0));
  // A span the triple-rocker cannot turn through.
  CHECK_FALSE(worstTransmissionOver(kTripleRocker, {0.0, 2.0 * kPi}).has_value());
}

TEST_CASE("Link-length defects", "[synthesis][defects]") {
  DefectBounds b = noBounds();
  b.maxLinkLength = 65.0;
  const auto longLink = checkFourBar({kThesis}, b);
  REQUIRE(has(longLink, DefectKind::LinkLength));
  CHECK(longLink.defects.back().message.find("coupler") != std::string::npos);
  b.maxLinkLength = 70.0;
  CHECK_FALSE(has(checkFourBar({kThesis}, b), DefectKind::LinkLength));
  b.maxLinkRatio = 2.5;  // 70 / 25 = 2.8
  CHECK(has(checkFourBar({kThesis}, b), DefectKind::LinkLength));
  b.maxLinkRatio = 2.8;
  CHECK_FALSE(has(checkFourBar({kThesis}, b), DefectKind::LinkLength));
}
