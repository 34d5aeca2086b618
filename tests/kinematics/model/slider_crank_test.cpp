// The slider-crank on the general model: closure, exact rates against finite differences and
// the closed-form piston law, the LS3 engine's piston extremes against the SolidWorks figures of
// seed 003, and its errors.

#include "kinematics/model/slider_crank.h"
#include "kinematics/analysis/mobility.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>

using namespace linkwright::kinematics;

namespace {

// LS3: stroke 92 mm (crank 46 mm), connecting rod 6.098 in = 154.8892 mm (seed 003).
constexpr SliderCrankGeometry kLs3{46.0, 6.098 * 25.4, 0.0, false};

// Piston position along the guide for an in-line slider-crank, x = r cos θ + √(L² − r² sin² θ).
double pistonX(double r, double l, double theta) {
  return r * std::cos(theta) + std::sqrt(l * l - r * r * std::sin(theta) * std::sin(theta));
}

}  // namespace

TEST_CASE("a slider-crank closes its loop and has mobility 1", "[model][slider-crank]") {
  const auto m = makeSliderCrank({30.0, 100.0, 12.0, false});
  REQUIRE(m.ok());
  CHECK(mobility(*m).mobility == 1);
  for (double deg = 0.0; deg < 360.0; deg += 15.0) {
    CAPTURE(deg);
    const auto pose = solvePose(*m, {degToRad(deg), 3.0, 0.7});
    REQUIRE(pose.ok());
    const Eigen::Vector2d b = pose->position[slidercrank::kB.index];
    const Eigen::Vector2d c = pose->position[slidercrank::kC.index];
    CHECK(b.norm() == Approx(30.0).epsilon(1e-14));
    CHECK((c - b).norm() == Approx(100.0).epsilon(1e-14));
    CHECK(c.y() == Approx(12.0).epsilon(1e-14));              // on the guide
    CHECK(pose->velocity[slidercrank::kC.index].y() == 0.0);  // moves along it only
  }
}

TEST_CASE("slider rates equal the derivatives of the closed-form piston law", "[model][slider-crank]") {
  // With ω constant, v = ω dx/dθ and a = ω² d²x/dθ²; central differences of the exact law, step
  // 1e-4 rad: truncation ~h²·x'''' ≈ 1e-8 relative, far below the 1e-6 tolerance.
  const auto m = makeSliderCrank({46.0, 154.8892, 0.0, false});
  REQUIRE(m.ok());
  const double omega = 2.0 * kPi * 110.0;
  const double h = 1e-4;
  for (double deg = 5.0; deg < 360.0; deg += 37.0) {
    CAPTURE(deg);
    const double t = degToRad(deg);
    const auto pose = solvePose(*m, {t, omega, 0.0});
    REQUIRE(pose.ok());
    const double x0 = pistonX(46.0, 154.8892, t);
    const double dx = (pistonX(46.0, 154.8892, t + h) - pistonX(46.0, 154.8892, t - h)) / (2 * h);
    const double d2x = (pistonX(46.0, 154.8892, t + h) - 2 * x0 + pistonX(46.0, 154.8892, t - h)) / (h * h);
    CHECK(pose->position[slidercrank::kC.index].x() == Approx(x0).epsilon(1e-14));
    CHECK(pose->velocity[slidercrank::kC.index].x() == Approx(omega * dx).epsilon(1e-6).margin(1e-6 * omega * 46.0));
    CHECK(pose->acceleration[slidercrank::kC.index].x() ==
          Approx(omega * omega * d2x).epsilon(1e-5).margin(1e-5 * omega * omega * 46.0));
  }
}

TEST_CASE("LS3 piston extremes agree with the SolidWorks figures of seed 003", "[model][slider-crank][published]") {
  // Seed 003, Table 3 (SolidWorks, one frame per degree): 22 Hz 6.63 m/s, 1139.9 m/s²;
  // 66 Hz 19.9 m/s, 10259.41 m/s²; 110 Hz 33.17 m/s, 28497.18 m/s². Velocities are printed to
  // two decimals; the accelerations differ from exact kinematics by up to 0.01 % (the paper
  // itself quotes 0.03 % between its MATLAB and SolidWorks values), so 0.02 % here.
  const auto [hz, vMax, aMax] = GENERATE(table<double, double, double>({
      {22.0, 6.63, 1139.9},
      {66.0, 19.9, 10259.41},
      {110.0, 33.17, 28497.18},
  }));
  CAPTURE(hz);
  const auto m = makeSliderCrank(kLs3);
  REQUIRE(m.ok());
  const auto s = sweep(*m, {0.0, 2.0 * kPi, 36001, 2.0 * kPi * hz, 0.0});
  REQUIRE(s.ok());
  double v = 0.0;
  double a = 0.0;
  for (std::size_t j = 0; j < s->size(); ++j) {
    REQUIRE(s->ok(j));
    v = std::max(v, std::abs(s->velocity[slidercrank::kC.index][j].x()) / 1000.0);  // mm/s → m/s
    a = std::max(a, std::abs(s->acceleration[slidercrank::kC.index][j].x()) / 1000.0);
  }
  CHECK(v == Approx(vMax).margin(0.005 + 1e-9));
  CHECK(a == Approx(aMax).epsilon(2e-4));
}

TEST_CASE("slider-crank errors name the field and the reason", "[model][slider-crank][errors]") {
  const auto badRod = makeSliderCrank({46.0, -1.0, 0.0, false});
  REQUIRE_FALSE(badRod.ok());
  CHECK(badRod.error().field == "rod");
  CHECK_THAT(badRod.error().message, Catch::Contains("rod length must be positive and finite (got -1)"));
  const auto badOffset = makeSliderCrank({46.0, 150.0, NAN, false});
  REQUIRE_FALSE(badOffset.ok());
  CHECK(badOffset.error().field == "offset");
  // Offset 100 with crank 30 and rod 60: at 90° B is 70 below the guide... out of the rod's reach.
  const auto far = makeSliderCrank({30.0, 60.0, 100.0, false});
  REQUIRE(far.ok());
  const auto pose = solvePose(*far, {degToRad(270.0), 1.0, 0.0});
  REQUIRE_FALSE(pose.ok());
  CHECK(pose.error().code == ErrorCode::NotAssemblable);
  CHECK_THAT(pose.error().message, Catch::Contains("B is 130 mm from the guide, more than the rod length 60 mm"));
}

TEST_CASE("a reversed slider-crank mirrors the usual one", "[model][slider-crank]") {
  const auto usual = makeSliderCrank({30.0, 100.0, 0.0, false});
  const auto reversed = makeSliderCrank({30.0, 100.0, 0.0, true});
  REQUIRE(usual.ok());
  REQUIRE(reversed.ok());
  const auto p = solvePose(*usual, {0.3, 2.0, 0.0});
  const auto q = solvePose(*reversed, {kPi - 0.3, -2.0, 0.0});  // the mirror image about the y axis
  REQUIRE(p.ok());
  REQUIRE(q.ok());
  CHECK(q->position[slidercrank::kC.index].x() == Approx(-p->position[slidercrank::kC.index].x()));
  CHECK(q->velocity[slidercrank::kC.index].x() == Approx(-p->velocity[slidercrank::kC.index].x()));
}
