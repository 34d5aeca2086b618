// Design: validation names the field; a four-bar design holds makeFourBar's mechanism and its
// grid matches the design.

#include "kinematics/design/design.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>

using namespace linkwright::kinematics;

TEST_CASE("checkDesign names the first invalid field", "[model][design][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Design d = fourBarDesign({60, 25, 70, 45}).value();
  CHECK_FALSE(checkDesign(d).has_value());
  const FourBarStructure s = asFourBar(d.mechanism).value();
  auto expectField = [](const Design& bad, const std::string& field, const std::string& message) {
    const auto e = checkDesign(bad);
    REQUIRE(e.has_value());
    CHECK(e->field == field);
    CHECK_THAT(e->message, Catch::Contains(message));
  };
  Design bad = d;
  bad.mechanism = withFourBarLengths(d.mechanism, s, {60, 25, 70, -1});
  expectField(bad, "lengths.rocker", "rocker length must be positive and finite (got -1)");
  bad = d;
  bad.omega = nan;
  expectField(bad, "omega", "omega must be finite and within ±1e6 rad/s (got undefined)");
  bad = d;
  bad.mechanism = withCouplerPoint(d.mechanism, s, CouplerPointSpec{1.0, INFINITY}).value();
  expectField(bad, "points[4].across", "must be finite (got undefined)");
  bad = d;
  bad.toDeg = bad.fromDeg;
  expectField(bad, "toDeg", "toDeg must be greater than fromDeg");
  bad = d;
  bad.samples = 1;
  expectField(bad, "samples", "samples must be between 2 and 10000000 (got 1)");

  // Any other linkage's lengths are named by their point.
  Design slider = designForExample("ls3-engine").value();
  CHECK_FALSE(checkDesign(slider).has_value());
  std::get<CrankPoint>(slider.mechanism.points[slider.mechanism.findPoint("B")->index].definition).length = -1;
  const auto e = checkDesign(slider);
  REQUIRE(e.has_value());
  CHECK(e->field == "points[" + std::to_string(slider.mechanism.findPoint("B")->index) + "].length");
  CHECK_THAT(e->message, Catch::Contains("must be positive and finite (got -1)"));
}

TEST_CASE("a four-bar design holds makeFourBar's mechanism and the old defaults", "[model][design]") {
  const auto d = fourBarDesign({80, 20, 66, 56}, Branch::Crossed, "mm", CouplerPointSpec{10, 5});
  REQUIRE(d.ok());
  CHECK(d->kind == "four-bar");
  CHECK(d->mechanism == makeFourBar({80, 20, 66, 56}, Branch::Crossed, "mm", CouplerPointSpec{10, 5}).value());
  CHECK(d->omega == 1.0);
  CHECK(d->alpha == 0.0);
  CHECK(d->fromDeg == 0.0);
  CHECK(d->toDeg == 360.0);
  CHECK(d->samples == 721);
  CHECK(d->dynamics.empty());
  CHECK_FALSE(checkDesign(*d).has_value());

  const auto bad = fourBarDesign({80, 20, -66, 56});
  REQUIRE_FALSE(bad.ok());
  CHECK(bad.error().field == "coupler");
}

TEST_CASE("a design's grid is its angles, samples and crank speed", "[model][design]") {
  Design d = fourBarDesign({80, 20, 66, 56}, Branch::Crossed, "mm", CouplerPointSpec{10, 5}).value();
  d.omega = 10.5;
  d.fromDeg = 0;
  d.toDeg = 320;
  d.samples = 9;
  const SweepSpec spec = designSweepSpec(d);
  CHECK(spec.samples == 9);
  CHECK(spec.omega == 10.5);
  CHECK(radToDeg(sweepAngle(spec, 1)) == Approx(40.0));
  CHECK(radToDeg(spec.toAngle) == Approx(320.0));
}

TEST_CASE("an example becomes a design sampled every half degree", "[model][design]") {
  const auto e = findExample("thesis-crank-rocker");
  REQUIRE(e.has_value());
  const Design d = designFromExample(*e);
  CHECK(d.kind == "four-bar");
  CHECK(d.mechanism == e->mechanism);
  CHECK(asFourBar(d.mechanism).value().lengths == FourBarLengths{60, 25, 70, 45});
  CHECK(d.omega == e->omega);
  CHECK(d.samples == 721);  // 0° to 360° every 0.5°
  CHECK(designForExample("thesis-crank-rocker") == d);
  CHECK_FALSE(designForExample("no-such-example").has_value());
}
