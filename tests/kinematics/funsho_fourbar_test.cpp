// Seed 004 (Funsho): the four-bar's joint forces and motor torque, against the seed's own
// method re-implemented here: its closed-form kinematics and its 9×9 Newton–Euler matrix,
// exactly as its MATLAB code writes them.
//
// The seed's table and code disagree. Table 1: coupler BC 0.4 kg, 0.004 kg·m²; rocker CD's
// centre rG = 15 mm. MATLAB code: m2 = 0.6 kg, ig2 = 0.0004 kg·m², rg3 = r3/2 = 10 mm (from C,
// the midpoint). The example funsho-fourbar uses the code's values: they produced the seed's
// published figures (polar load diagrams, motor torque). Crank and rocker agree (0.2 kg,
// 1e-5 kg·m²; 0.4 kg, 8e-5 kg·m²; crank centre 5 mm).
//
// The seed's conventions: r1 = AB (crank), r2 = BC, r3 = CD, r4 = AD along +x; TH3 is the
// direction C→D (so D = C + r3·e3), TH2 the direction B→C. Unknowns XA, YA (on AB at A from the
// ground), XB, YB (on AB at B from BC), XC, YC (on BC at C from CD), XD, YD (on CD at D from the
// ground), TM (on AB, CCW). Ours: F_O2 = force on the crank from the ground = (XA, YA); F_B =
// on the coupler from the crank = −(XB, YB); F_C = on the rocker from the coupler = −(XC, YC);
// F_O4 = on the rocker from the ground = (XD, YD); T_drive = TM.

#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"

#include <Eigen/Dense>

#include <cmath>

using namespace linkwright::kinematics;

namespace {

struct SeedForces {
  Eigen::Vector2d a, b, c, d;  // XA..YD as the seed defines them
  double tm = 0.0;
};

// The seed's MATLAB, line by line (w1 = 100 rad/s, a1 = 0), at crank angle th1.
SeedForces seedMethod(double th1) {
  const double r1 = 0.01, r2 = 0.035, r3 = 0.02, r4 = 0.03;
  const double rg1 = r1 / 2, rg2 = r2 / 2, rg3 = r3 / 2;
  const double ig1 = 0.00001, ig2 = 0.0004, ig3 = 0.00008;
  const double w1 = 100.0, a1 = 0.0;
  const double m1 = 0.2, m2 = 0.6, m3 = 0.4;
  const double A = std::cos(th1) - r4 / r1;
  const double B = std::sin(th1);
  const double C = (r4 / r3) * std::cos(th1) - (r1 * r1 - r2 * r2 + r3 * r3 + r4 * r4) / (2 * r1 * r3);
  const double R = std::sqrt(A * A + B * B);
  const double Z = C / R;
  const double zz = std::sqrt(1 - Z * Z);
  const double th3 = std::atan2(B, A) + std::atan2(zz, Z);
  const double th2 = std::atan2(-r3 * std::sin(th3) - r1 * std::sin(th1), r4 - r3 * std::cos(th3) - r1 * std::cos(th1));
  const double w3 = w1 * (r1 * std::sin(th1 - th2)) / (r3 * std::sin(th2 - th3));
  const double w2 = w1 * (r1 * std::sin(th3 - th1)) / (r2 * std::sin(th2 - th3));
  const double s23 = std::sin(th2 - th3);
  const double a3 =
      (w1 * w1 * r1 / r3) *
      ((1 - w2 / w1) * std::cos(th1 - th2) * s23 - (w2 / w1 - w3 / w1) * std::cos(th2 - th3) * std::sin(th1 - th2)) /
      (s23 * s23);
  const double a2 =
      -(w1 * w1 * r1 / r2) *
      ((1 - w3 / w1) * std::cos(th1 - th3) * s23 - (w2 / w1 - w3 / w1) * std::cos(th2 - th3) * std::sin(th1 - th3)) /
      (s23 * s23);
  const double xg1 = -rg1 * (a1 * std::sin(th1) + w1 * w1 * std::cos(th1));
  const double yg1 = rg1 * (a1 * std::cos(th1) - w1 * w1 * std::sin(th1));
  const double xg2 =
      -r1 * (a1 * std::sin(th1) + w1 * w1 * std::cos(th1)) - rg2 * (a2 * std::sin(th2) + w2 * w2 * std::cos(th2));
  const double yg2 =
      r1 * (a1 * std::cos(th1) - w1 * w1 * std::sin(th1)) + rg2 * (a2 * std::cos(th2) - w2 * w2 * std::sin(th2));
  const double xg3 = (r3 - rg3) * (a3 * std::sin(th3) + w3 * w3 * std::cos(th3));
  const double yg3 = -(r3 - rg3) * (a3 * std::cos(th3) - w3 * w3 * std::sin(th3));
  Eigen::Matrix<double, 9, 9> M;
  const double s1 = std::sin(th1), c1 = std::cos(th1), s2 = std::sin(th2), c2 = std::cos(th2);
  const double s3 = std::sin(th3), c3 = std::cos(th3);
  M << 1, 0, 1, 0, 0, 0, 0, 0, 0,                                             //
      0, 1, 0, 1, 0, 0, 0, 0, 0,                                              //
      rg1 * s1, -rg1 * c1, -(r1 - rg1) * s1, (r1 - rg1) * c1, 0, 0, 0, 0, 1,  //
      0, 0, -1, 0, 1, 0, 0, 0, 0,                                             //
      0, 0, 0, -1, 0, 1, 0, 0, 0,                                             //
      0, 0, -rg2 * s2, rg2 * c2, -(r2 - rg2) * s2, (r2 - rg2) * c2, 0, 0, 0,  //
      0, 0, 0, 0, -1, 0, 1, 0, 0,                                             //
      0, 0, 0, 0, 0, -1, 0, 1, 0,                                             //
      0, 0, 0, 0, -rg3 * s3, rg3 * c3, -(r3 - rg3) * s3, (r3 - rg3) * c3, 0;
  Eigen::Matrix<double, 9, 1> rhs;
  rhs << m1 * xg1, m1 * yg1, ig1 * a1, m2 * xg2, m2 * yg2, ig2 * a2, m3 * xg3, m3 * yg3, ig3 * a3;
  const Eigen::Matrix<double, 9, 1> x = M.fullPivLu().solve(rhs);
  return {{x(0), x(1)}, {x(2), x(3)}, {x(4), x(5)}, {x(6), x(7)}, x(8)};
}

}  // namespace

TEST_CASE("funsho-fourbar: joint forces and motor torque match the seed's 9×9 method",
          "[dynamics][published][funsho]") {
  const auto example = findExample("funsho-fourbar");
  REQUIRE(example.has_value());
  const auto fourBar = asFourBar(example->mechanism);
  REQUIRE(fourBar.has_value());
  CHECK(fourBar->lengths == FourBarLengths{30.0, 10.0, 35.0, 20.0});
  CHECK(example->omega == 100.0);
  const Mechanism m = makeFourBar(fourBar->lengths, fourBar->branch, example->mechanism.lengthUnit).value();
  CHECK(m == example->mechanism);
  // Every 5°: the seed steps 0.001 rad; both methods are exact, so any grid tests the same.
  const SweepSpec spec{0.0, 2.0 * kPi, 73, example->omega, example->alpha};
  const auto s = sweep(m, spec);
  REQUIRE(s.ok());
  const auto f = sweepForces(m, example->dynamics, *s);
  REQUIRE(f.ok());
  // Joints in our order O2, O4, B, C (rigid_bodies.h).
  for (std::size_t j = 0; j < s->size(); ++j) {
    const double deg = radToDeg(s->inputAngle[j]);
    CAPTURE(deg);
    REQUIRE(f->ok(j));
    const SeedForces seed = seedMethod(s->inputAngle[j]);
    // Both solve the same equations in double precision; the forces are a few to ~100 N and
    // agree to round-off amplified by the kinematics, so 1e-9 of the largest.
    const double scale = std::max({seed.a.norm(), seed.b.norm(), seed.c.norm(), seed.d.norm()});
    CHECK((f->revolute[0][j] - seed.a).norm() <= 1e-9 * scale);
    CHECK((f->revolute[1][j] - seed.d).norm() <= 1e-9 * scale);
    CHECK((f->revolute[2][j] + seed.b).norm() <= 1e-9 * scale);
    CHECK((f->revolute[3][j] + seed.c).norm() <= 1e-9 * scale);
    CHECK(f->driveTorque[j] == Approx(seed.tm).epsilon(0.0).margin(1e-9 * scale * 0.01));
  }
}

TEST_CASE("funsho-fourbar: the example carries the code's masses, midpoint centres and no gravity",
          "[dynamics][funsho]") {
  const auto example = findExample("funsho-fourbar");
  REQUIRE(example.has_value());
  const LinkageDynamics& d = example->dynamics;
  REQUIRE(d.links.size() == 3);
  CHECK(d.links[1].link == "coupler");
  CHECK(d.links[1].mass == 0.6);            // the code's m2 (the table says 0.4)
  CHECK(d.links[1].inertia == 4e-4);        // the code's ig2 (the table says 0.004)
  CHECK(d.links[2].centre->along == 10.0);  // rg3 = r3/2 (the table says 15 mm)
  CHECK_FALSE(d.loads.gravity.has_value());
  const auto fourBar = asFourBar(example->mechanism);
  REQUIRE(fourBar.has_value());
  CHECK_FALSE(checkDynamics(makeFourBar(fourBar->lengths, fourBar->branch).value(), d).has_value());
}
