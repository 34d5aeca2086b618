// FourBarDesign: validation names the field; the built mechanism and grid match the design.

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

using namespace linkwright::kinematics;

TEST_CASE("checkDesign names the first invalid field", "[model][design][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  FourBarDesign d;
  CHECK_FALSE(checkDesign(d).has_value());
  auto expectField = [](FourBarDesign bad, const std::string& field, const std::string& message) {
    const auto e = checkDesign(bad);
    REQUIRE(e.has_value());
    CHECK(e->field == field);
    CHECK_THAT(e->message, Catch::Contains(message));
  };
  FourBarDesign bad = d;
  bad.lengths.rocker = -1;
  expectField(bad, "lengths.rocker", "rocker length must be positive and finite (got -1)");
  bad = d;
  bad.omega = nan;
  expectField(bad, "omega", "omega must be finite and within ±1e6 rad/s (got nan)");
  bad = d;
  bad.couplerPoint = CouplerPointSpec{1.0, INFINITY};
  expectField(bad, "couplerPoint.across", "must be finite (got inf)");
  bad = d;
  bad.toDeg = bad.fromDeg;
  expectField(bad, "toDeg", "toDeg must be greater than fromDeg");
  bad = d;
  bad.samples = 1;
  expectField(bad, "samples", "samples must be between 2 and 10000000 (got 1)");
}

TEST_CASE("a design builds its four-bar and grid", "[model][design]") {
  FourBarDesign d;
  d.lengths = {80, 20, 66, 56};
  d.branch = Branch::Crossed;
  d.couplerPoint = CouplerPointSpec{10, 5};
  d.omega = 10.5;
  d.fromDeg = 0;
  d.toDeg = 320;
  d.samples = 9;
  const auto m = buildMechanism(d);
  REQUIRE(m.ok());
  CHECK(*m == makeFourBar(d.lengths, Branch::Crossed, "mm", CouplerPointSpec{10, 5}).value());
  const SweepSpec spec = designSweepSpec(d);
  CHECK(spec.samples == 9);
  CHECK(spec.omega == 10.5);
  CHECK(radToDeg(sweepAngle(spec, 1)) == Approx(40.0));
  CHECK(radToDeg(spec.toAngle) == Approx(320.0));
}

TEST_CASE("an example becomes a design sampled every half degree", "[model][design]") {
  const auto e = findFourBarExample("thesis-crank-rocker");
  REQUIRE(e.has_value());
  const FourBarDesign d = designFromExample(*e);
  CHECK(d.lengths == e->lengths);
  CHECK(d.omega == e->omega);
  CHECK(d.samples == 721);  // 0° to 360° every 0.5°
}
