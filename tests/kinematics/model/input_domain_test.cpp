// The input domain (kinematics/model/validate.h): each bound accepts its own value and refuses
// the next double past it with the field, the value and the range; and at the corners of the
// domain, every input at its bound at once, every output of a sweep and of the forces is
// finite — the promise the bounds are derived from.

#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>

using namespace linkwright::kinematics;

namespace {

double above(double x) { return std::nextafter(x, std::numeric_limits<double>::infinity()); }
double below(double x) { return std::nextafter(x, 0.0); }

bool allFinite(const SweepResult& s) {
  for (const auto* columns : {&s.position, &s.velocity, &s.acceleration})
    for (const auto& column : *columns)
      for (const Eigen::Vector2d& v : column)
        if (!v.allFinite()) return false;
  for (const auto* columns : {&s.linkAngle, &s.linkOmega, &s.linkAlpha})
    for (const auto& column : *columns)
      for (const double v : column)
        if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

TEST_CASE("each bound accepts its value and refuses the next double with the field, value and range",
          "[domain][errors]") {
  CHECK_FALSE(checkLength(kMinLength, "crank"));
  CHECK_FALSE(checkLength(kMaxLength, "crank"));
  CHECK(checkLength(below(kMinLength), "crank")->message ==
        "crank length must be between 1e-6 and 1e9 (got 9.999999999999997e-07)");
  CHECK(checkLength(above(kMaxLength), "crank")->message ==
        "crank length must be between 1e-6 and 1e9 (got 1000000000.0000001)");
  CHECK(checkLength(-70.0, "coupler")->message == "coupler length must be positive and finite (got -70)");
  CHECK_FALSE(checkCoordinate(-kMaxLength, "O4.x"));
  CHECK(checkCoordinate(above(kMaxLength), "O4.x")->message == "O4.x must be within ±1e9 (got 1000000000.0000001)");
  CHECK(checkCoordinate(std::nan(""), "O4.x")->message == "O4.x must be finite (got undefined)");
  CHECK_FALSE(checkMagnitude(-kMaxOmega, "omega", kMaxOmega, "rad/s"));
  CHECK(checkMagnitude(above(kMaxOmega), "omega", kMaxOmega, "rad/s")->field == "omega");
  CHECK_FALSE(checkNonNegative(kMaxMass, "mass", kMaxMass, "kg"));
  CHECK(checkNonNegative(-0.0 - 1e-300, "mass", kMaxMass, "kg")->message ==
        "mass must be between 0 and 1e9 kg (got -1e-300)");
}

TEST_CASE("a linkage may span at most 1e6 times its shortest link", "[domain][errors]") {
  CHECK(makeFourBar({1e6, 1.0, 2.0, 1e6}, Branch::Open).ok());  // exactly 1e6: measured in stability_test.cpp
  const auto wide = makeFourBar({above(1e6), 1.0, 2.0, 1e6}, Branch::Open);
  REQUIRE_FALSE(wide.ok());
  CHECK(wide.error().field == "lengths");
  CHECK(wide.error().message ==
        "lengths span too wide a range: link crank is 1 mm but O4.x is 1000000.0000000001 mm, "
        "1e+06 times as much; a linkage's largest dimension may be at most 1e6 times its shortest link");
  // Coordinates count too: a slider's guide far from a short crank.
  const auto far = makeSliderCrank({1e-3, 2e-3, 2e3, false});
  REQUIRE_FALSE(far.ok());
  CHECK_THAT(far.error().message, Catch::Contains("link crank is 0.001 mm but C.guide.y is 2000 mm"));
}

TEST_CASE("sweeps refuse speeds, angles and sample counts outside the domain", "[domain][errors]") {
  const Mechanism m = makeFourBar({60, 25, 70, 45}, Branch::Open).value();
  CHECK(sweep(m, {0.0, 1.0, 2, kMaxOmega, kMaxAlpha}).ok());
  CHECK(sweep(m, {0.0, 1.0, 2, above(kMaxOmega), 0.0}).error().field == "omega");
  CHECK(sweep(m, {0.0, 1.0, 2, 1.0, above(kMaxAlpha)}).error().field == "alpha");
  CHECK(sweep(m, {0.0, 1.0, static_cast<std::size_t>(kMaxSamples) + 1, 1.0, 0.0}).error().message ==
        "samples must be between 1 and 10000000 (got 10000001)");
}

TEST_CASE("at the domain's corners every kinematic and force output is finite", "[domain]") {
  // Largest lengths with the largest spread, at the largest ω and α; and the smallest.
  const auto [lengths, unit] = GENERATE(table<FourBarLengths, const char*>({
      {{kMaxLength, kMaxLength / kMaxLengthRatio, kMaxLength, kMaxLength}, "m"},
      {{kMinLength * kMaxLengthRatio, kMinLength, kMinLength * kMaxLengthRatio, kMinLength * kMaxLengthRatio}, "mm"},
  }));
  CAPTURE(lengths.frame, lengths.crank);
  const Mechanism m = makeFourBar(lengths, Branch::Open, unit).value();
  for (const double omega : {kMaxOmega, -kMaxOmega}) {
    const auto s = sweep(m, {0.0, 2.0 * 3.141592653589793, 73, omega, kMaxAlpha});
    REQUIRE(s.ok());
    CHECK(s->notAssembled.empty());
    CHECK(allFinite(*s));
    // Heaviest links with the largest loads.
    LinkageDynamics d;
    for (const char* link : {"crank", "coupler", "rocker"})
      d.links.push_back({link, kMaxMass, std::nullopt, kMaxInertia});
    d.loads.gravity = Eigen::Vector2d(kMaxGravity, -kMaxGravity);
    d.loads.torques.push_back({"rocker", kMaxTorque});
    d.loads.forces.push_back({"coupler", "C", 0, Eigen::Vector2d(kMaxForce, -kMaxForce)});
    const auto f = sweepForces(m, d, *s);
    REQUIRE(f.ok());
    for (std::size_t j = 0; j < f->size(); ++j) {
      CHECK(std::isfinite(f->driveTorque[j]));
      CHECK(f->shakingForce[j].allFinite());
      CHECK(std::isfinite(f->shakingMoment[j]));
      for (const auto& joint : f->revolute) CHECK(joint[j].allFinite());
    }
  }
}
