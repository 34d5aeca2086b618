// The refined extremes of a force over a sweep (force_extrema.h): found between samples on poses
// solved afresh, they match the closed form however coarse the sweep, and never fall short of
// the best sample.

#include "kinematics/dynamics/force_extrema.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

TEST_CASE("a slider's shaking force peaks at m r ω² (1 + r/L) at top dead centre, found from 13 samples",
          "[dynamics][extrema]") {
  // The LS3 piston alone has mass: the frame feels −m a of the piston, largest at top dead
  // centre, where a = r ω² (1 + r/L).
  const double r = 46.0, l = 154.8892, omega = 2.0 * kPi * 110.0, mass = 0.6;
  const Mechanism m = makeSliderCrank({r, l, 0.0, false}).value();
  LinkageDynamics d;
  d.sliders.push_back({m.points[slidercrank::kC.index].name, 0, mass, 0.0});
  const SweepSpec spec{0.1, 0.1 + 2.0 * kPi, 13, omega, 0.0};
  const auto s = sweep(m, spec);
  REQUIRE(s.ok());
  const auto forces = sweepForces(m, d, *s);
  REQUIRE(forces.ok());
  double sampled = 0.0;
  for (std::size_t j = 0; j < forces->size(); ++j) sampled = std::max(sampled, forces->shakingForce[j].norm());
  const auto peaks = shakingPeaks(m, d, spec, *forces);
  REQUIRE(peaks);
  const double exact = mass * r / 1000.0 * omega * omega * (1.0 + r / l);
  CHECK(peaks->force.value == Approx(exact).epsilon(1e-9));
  CHECK(std::remainder(peaks->force.inputAngle, 2.0 * kPi) == Approx(0.0).margin(1e-4));
  CHECK(peaks->force.refined);
  CHECK(sampled < exact * (1.0 - 1e-4));  // the best of 13 samples misses it
  // No mass on any link: the moment about the crank pivot is the piston's force times its
  // offset, 0 on an in-line slider-crank's guide.
  CHECK(std::abs(peaks->moment.value) <= 1e-9 * exact * r / 1000.0);
}
