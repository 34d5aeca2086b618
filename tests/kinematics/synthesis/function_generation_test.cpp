// Tests kinematics/synthesis/function_generation.h with y = log10 x on [1, 10] (the classic
// example of Freudenstein's method in Norton's and Wilson & Sadler's texts): the Chebyshev points
// are the textbook's; the synthesised design, solved by the pose solver in the test, meets the
// wanted output exactly at the precision points and its structural error equals the test's own
// evaluation everywhere; the peak is a true maximum; least squares satisfies its normal
// equations; defects and bad targets are reported; a published three-position lecture problem
// (Ohio State ME 3751, after Waldron & Kinzel) is reproduced, its printing slips explained.

#include "kinematics/synthesis/function_generation.h"

#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <Eigen/Dense>

#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::within;

namespace {

double log10x(double x) { return std::log10(x); }

FunctionTarget logTarget(double inStartDeg, double inSpanDeg, double outStartDeg, double outSpanDeg) {
  return {log10x, 1.0, 10.0, degToRad(inStartDeg), degToRad(inSpanDeg), degToRad(outStartDeg), degToRad(outSpanDeg),
          50.0,   "mm"};
}

// The design's output error at x, as this test computes it: the rocker's angle from the pose
// solver (less π if the rocker points the other way) against the wanted angle.
double independentError(const FunctionTarget& t, const FunctionSynthesis& s, double x) {
  const double theta2 = t.inputStart + t.inputSpan * (x - t.x0) / (t.x1 - t.x0);
  const double wanted = t.outputStart + t.outputSpan * (std::log10(x) - 0.0) / (1.0 - 0.0);
  const auto pose = solvePose(s.candidate.design.mechanism, {theta2, 0.0, 0.0}, {false, false});
  REQUIRE(pose.ok());
  const double rocker = pose->linkAngle[fourbar::kRocker.index] + (s.linkage.rockerReversed ? kPi : 0.0);
  return angleDifference(rocker, wanted);
}

}  // namespace

TEST_CASE("Chebyshev spacing: the textbook's three points on [1, 10]", "[synthesis][function]") {
  // x_j = 5.5 − 4.5 cos((2j − 1)·30°): 1.6029, 5.5, 9.3971 (printed to four digits in the texts).
  const auto x = chebyshevSpacing(1.0, 10.0, 3);
  REQUIRE(x.size() == 3);
  CHECK(x[0] == within(5.5 - 4.5 * std::sqrt(3.0) / 2.0, 1e-14));
  CHECK(x[1] == within(5.5, 1e-14));
  CHECK(x[2] == within(5.5 + 4.5 * std::sqrt(3.0) / 2.0, 1e-14));
  CHECK(x[0] == within(1.6029, 5e-5));
  CHECK(x[2] == within(9.3971, 5e-5));
}

TEST_CASE("log10 generator: exact at the precision points, structural error as solved", "[synthesis][function]") {
  // Two mappings: one builds its crank reversed (Freudenstein gives a < 0), one its rocker.
  const auto [inStart, inSpan, outStart, outSpan] =
      GENERATE(table<double, double, double, double>({{60, 120, 240, 60}, {30, 90, 90, 90}, {45, 60, 135, 90}}));
  CAPTURE(inStart, inSpan, outStart, outSpan);
  const FunctionTarget t = logTarget(inStart, inSpan, outStart, outSpan);
  const auto s = synthesiseFunction(t);
  REQUIRE(s.ok());
  REQUIRE(asFourBar(s->candidate.design.mechanism).has_value());
  CHECK(s->linkage.lengths.frame == 50.0);
  // At the precision points the linkage, solved afresh, gives exactly the wanted output.
  for (const double x : s->points) {
    CAPTURE(x);
    CHECK(independentError(t, *s, x) == within(0.0, 1e-9));
  }
  // The reported curve is the test's own evaluation, sample by sample.
  REQUIRE(s->error.x.size() + s->error.notAssembled.size() == 201);
  for (std::size_t i = 0; i < s->error.x.size(); i += 10) {
    CAPTURE(s->error.x[i]);
    CHECK(s->error.outputError[i] == within(independentError(t, *s, s->error.x[i]), 1e-12));
  }
  // The peak bounds every sample and is where it is said to be.
  for (const double e : s->error.outputError) CHECK(std::abs(e) <= s->error.maxAbs + 1e-15);
  CHECK(std::abs(independentError(t, *s, s->error.maxAt)) == within(s->error.maxAbs, 1e-12));
  CHECK(s->candidate.error == s->error.maxAbs);
  CHECK(s->error.maxAbsY == within(s->error.maxAbs / std::abs(t.outputSpan), 1e-15));  // y spans 1
}

TEST_CASE("log10 generator: the first mapping has a reversed crank and no defect", "[synthesis][function]") {
  const auto s = synthesiseFunction(logTarget(60, 120, 240, 60));
  REQUIRE(s.ok());
  CHECK(s->linkage.crankReversed);
  CHECK(s->error.notAssembled.empty());
  CHECK(s->candidate.defects.empty());
  CHECK(s->candidate.minTransmission > degToRad(40.0));
}

TEST_CASE("log10 generator: a mapping whose range cannot be assembled is marked, not dropped",
          "[synthesis][function][defects]") {
  const auto s = synthesiseFunction(logTarget(45, 60, 135, 90));
  REQUIRE(s.ok());
  CHECK_FALSE(s->error.notAssembled.empty());
  CHECK(s->candidate.has(DefectKind::Branch));
  // One whose precision positions lie on different branches.
  const auto split = synthesiseFunction(logTarget(90, 60, 270, 90));
  REQUIRE(split.ok());
  CHECK(split->candidate.has(DefectKind::Branch));
  CHECK(split->candidate.has(DefectKind::Transmission));
}

TEST_CASE("Least squares over five Chebyshev points satisfies the normal equations", "[synthesis][function]") {
  const FunctionTarget t = logTarget(60, 120, 240, 60);
  const auto s = synthesiseFunction(t, {{}, 5});
  REQUIRE(s.ok());
  REQUIRE(s->precisionAngles.size() == 5);
  // Mᵀ(M K − r) = 0 with the rows [cos θ4, −cos θ2, 1] and r = cos(θ2 − θ4).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (const AnglePair& p : s->precisionAngles) {
    const double residual = freudensteinResidual(s->k, p);
    normal += residual * Eigen::Vector3d(std::cos(p.output), -std::cos(p.input), 1.0);
  }
  CHECK(normal.norm() < 1e-13);
  // Not an interpolation: the equation's residual is not zero at every point.
  double largest = 0.0;
  for (const AnglePair& p : s->precisionAngles) largest = std::max(largest, std::abs(freudensteinResidual(s->k, p)));
  CHECK(largest > 1e-6);
}

TEST_CASE("The user's own precision points are used as given", "[synthesis][function]") {
  const FunctionTarget t = logTarget(60, 120, 240, 60);
  const auto s = synthesiseFunction(t, {{2.0, 5.0, 8.0}});
  REQUIRE(s.ok());
  CHECK(s->points == std::vector<double>{2.0, 5.0, 8.0});
  for (const double x : s->points) CHECK(independentError(t, *s, x) == within(0.0, 1e-9));
}

TEST_CASE("Bad function targets are errors naming the field", "[synthesis][function][errors]") {
  FunctionTarget good = logTarget(60, 120, 240, 60);
  const auto fieldOf = [](const FunctionTarget& t, const FunctionOptions& o = {}) {
    const auto s = synthesiseFunction(t, o);
    REQUIRE_FALSE(s.ok());
    CHECK_FALSE(s.error().message.empty());
    return s.error().field;
  };
  FunctionTarget t = good;
  t.x1 = 1.0;  // empty range
  CHECK(fieldOf(t) == "x1");
  t.x1 = 0.5;  // reversed
  CHECK(fieldOf(t) == "x1");
  t = good;
  t.x0 = NAN;
  CHECK(fieldOf(t) == "x0");
  t = good;
  t.inputSpan = 0.0;
  CHECK(fieldOf(t) == "inputSpan");
  t = good;
  t.outputSpan = 7.0;  // more than a turn
  CHECK(fieldOf(t) == "outputSpan");
  t = good;
  t.frame = 0.0;
  CHECK(fieldOf(t) == "frame");
  t = good;
  t.f = nullptr;
  CHECK(fieldOf(t) == "function");
  t = good;
  t.x0 = -1.0;  // log10 is NaN there
  CHECK(fieldOf(t) == "function");
  t = good;
  t.f = [](double x) { return x * x; };
  t.x0 = -1.0;
  t.x1 = 1.0;  // f(x0) = f(x1)
  CHECK(fieldOf(t) == "function");
  CHECK(fieldOf(good, {{2.0, 5.0}}) == "points");
  CHECK(fieldOf(good, {{2.0, 5.0, 5.0}}) == "points[2]");   // coincident
  CHECK(fieldOf(good, {{2.0, 5.0, 11.0}}) == "points[2]");  // outside [x0, x1]
  CHECK(fieldOf(good, {{}, 2}) == "count");
  CHECK(fieldOf(good, {{}, 3, 1}) == "samples");
}

TEST_CASE("Published example: three rocker positions, Ohio State ME 3751 Lecture 12 (Waldron & Kinzel 3.2)",
          "[synthesis][function][published]") {
  // H.-J. Su, ME 3751 "Kinematics and mechanisms", Lecture 12 "Analytical synthesis of 4-bar
  // with three rocker positions" (after Waldron & Kinzel, sec. 3.2), the lecture problem on
  // slides 12-13 (the PDF in github.com/haijunsu-osu/rocker_synthesis_4bar):
  // θ = 35.02°, 67.50°, 100.0° with φ = 91.21°, 101.79°, 117.19°, base link
  // r1 = 4.5 in. Its z1, z2, z3 are our K3, K1, K2 (same equation, same signs). Printed:
  // z = 5.150, 11.20, 5.321; R2 = 0.4018, R3 = 4.198, R4 = 0.8456 in.
  // Those printed numbers are 0.07 % to 1.0 % off the exact solution of the slide's own angles.
  // Its matrix is rounded to four places and has 0.1732 for −cos 100° = 0.17365; even that
  // printed matrix solves to z = 5.186, 11.29, 5.364, so the printed z (and the lengths from
  // them) carry a further slip of about 1 %, which the ill-conditioned system (det 0.0083)
  // magnifies. We test the exact values, solved here by Eigen from the angles (not by the
  // synthesis), to 1e-9, and the printed ones within 1.2 %, the size of that published error.
  const double th[3] = {35.02, 67.5, 100.0}, ph[3] = {91.21, 101.79, 117.19};
  Eigen::Matrix3d m;
  Eigen::Vector3d rhs;
  for (int j = 0; j < 3; ++j) {
    m.row(j) << std::cos(degToRad(ph[j])), -std::cos(degToRad(th[j])), 1.0;
    rhs(j) = std::cos(degToRad(th[j] - ph[j]));
  }
  const Eigen::Vector3d k = m.partialPivLu().solve(rhs);  // K1, K2, K3
  // The CLI has no "these angle pairs" input, so the pairs are a function: φ is a quadratic in
  // θ through the three points, φ = C·x² + const with x = θ + B/2C, generated as `square` with
  // x at the three precision points (docs/synthesis.md gives the command).
  const double f01 = (ph[1] - ph[0]) / (th[1] - th[0]), f12 = (ph[2] - ph[1]) / (th[2] - th[1]);
  const double c2 = (f12 - f01) / (th[2] - th[0]), c1 = f01 - c2 * (th[0] + th[1]);
  const double shift = c1 / (2.0 * c2);
  const FunctionTarget t{[](double x) { return x * x; },
                         th[0] + shift,
                         th[2] + shift,
                         degToRad(th[0]),
                         degToRad(th[2] - th[0]),
                         degToRad(ph[0]),
                         degToRad(ph[2] - ph[0]),
                         4.5,
                         "in"};
  const auto s = synthesiseFunction(t, {{th[0] + shift, th[1] + shift, th[2] + shift}});
  REQUIRE(s.ok());
  REQUIRE(s->precisionAngles.size() == 3);
  for (int j = 0; j < 3; ++j) {
    CHECK(s->precisionAngles[j].input == within(degToRad(th[j]), 1e-12));
    CHECK(s->precisionAngles[j].output == within(degToRad(ph[j]), 1e-12));
  }
  CHECK(s->k.k1 == within(k(0), 1e-9 * k(0)));
  CHECK(s->k.k2 == within(k(1), 1e-9 * k(1)));
  CHECK(s->k.k3 == within(k(2), 1e-9 * k(2)));
  const FourBarLengths& l = s->linkage.lengths;
  CHECK_FALSE(s->linkage.crankReversed);
  CHECK_FALSE(s->linkage.rockerReversed);
  CHECK(l.frame == 4.5);
  CHECK(l.crank == within(4.5 / k(0), 1e-9));
  CHECK(l.rocker == within(4.5 / k(1), 1e-9));
  CHECK(l.coupler * l.coupler ==
        within(l.crank * l.crank + l.rocker * l.rocker + 4.5 * 4.5 - 2.0 * l.crank * l.rocker * k(2), 1e-9));
  // The slide's printed numbers, within their 1.2 % published error.
  CHECK(s->k.k3 == within(5.150, 0.012 * 5.150));
  CHECK(s->k.k1 == within(11.20, 0.012 * 11.20));
  CHECK(s->k.k2 == within(5.321, 0.012 * 5.321));
  CHECK(l.crank == within(0.4018, 0.012 * 0.4018));
  CHECK(l.coupler == within(4.198, 0.012 * 4.198));
  CHECK(l.rocker == within(0.8456, 0.012 * 0.8456));
  // The linkage, solved afresh by the pose solver, puts the rocker at each φ.
  for (int j = 0; j < 3; ++j) {
    CAPTURE(th[j]);
    const auto pose = solvePose(s->candidate.design.mechanism, {degToRad(th[j]), 0.0, 0.0}, {false, false});
    REQUIRE(pose.ok());
    CHECK(angleDifference(pose->linkAngle[fourbar::kRocker.index], degToRad(ph[j])) == within(0.0, 1e-9));
  }
}
