// Stability at the extremes (issue 5): the core driven where linkages are hardest, with its
// accuracy asserted against independent references computed in long double (64-bit mantissa,
// about 1e-19), not just "no crash". The four-bar reference takes link angles from the
// triangle B–C–O4 by atan2 of Heron's area and the law of cosines, and rates from the loop
// equation a·e2 + b·e3 = d + c·e4 and its derivatives (Norton's form); the slider-crank
// reference is x = a·cos θ + √(l² − (e − a·sin θ)²) differentiated by hand. The core uses none
// of these (it solves the foot-and-normal form and a 2×2 system per dyad, in double).
//
// Error measures, used in the names: angles and positions absolute (positions over the
// linkage's longest link); ω and α over the larger of the crank's rate scale (|ω2|, ω2² + |α2|)
// and the link's peak |ω| or |α| over the sweep, or plain relative |Δ|/|reference| at single
// poses. Each bound is the error reached, rounded up to the next 1, 2 or 5 in its decade;
// docs/accuracy.md tabulates them.

#include "kinematics/analysis/assembly_range.h"
#include "kinematics/analysis/grashof.h"
#include "kinematics/design/examples.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/rrr_dyad.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

using namespace linkwright::kinematics;
using linkwright::test::firstNonFinite;
using linkwright::test::kThesis;

namespace {

using Real = long double;
constexpr Real kPiL = 3.141592653589793238462643383279502884L;  // kPi is π rounded to double

constexpr auto kC = fourbar::kC.index;
constexpr auto kCoupler = fourbar::kCoupler.index;
constexpr auto kRocker = fourbar::kRocker.index;

// --- References in long double ---------------------------------------------------------------

struct FourBarReference {
  Real cx = 0, cy = 0;
  Real theta3 = 0, theta4 = 0, omega3 = 0, omega4 = 0, alpha3 = 0, alpha4 = 0;
  Real sinMu = 0;  // |sin| of the transmission angle at C
};

// `sign` +1 puts C left of B→O4 (Branch::Open), −1 right. Past an assembly limit the triangle
// is taken flat, as the core does within its tolerance.
FourBarReference fourBar(const FourBarLengths& l, double theta2, double omega2, double alpha2, int sign) {
  const Real a = l.crank, b = l.coupler, c = l.rocker, d = l.frame, s = sign;
  const Real w2 = omega2, al2 = alpha2;
  const Real c2 = std::cos(static_cast<Real>(theta2)), s2 = std::sin(static_cast<Real>(theta2));
  const Real bx = a * c2, by = a * s2;
  const Real len = std::hypot(d - bx, -by);
  const Real beta = std::atan2(-by, d - bx);  // direction B→O4
  const Real diff = std::abs(b - c);
  const Real area4 = std::sqrt(std::max(b + c - len, Real(0)) * (b + c + len) * std::max(len - diff, Real(0)) *
                               (len + diff));  // 4 × the triangle's area
  FourBarReference r;
  r.theta3 = beta + s * std::atan2(area4, b * b + len * len - c * c);         // angle at B
  r.theta4 = beta + kPiL - s * std::atan2(area4, c * c + len * len - b * b);  // angle at O4
  r.cx = bx + b * std::cos(r.theta3);
  r.cy = by + b * std::sin(r.theta3);
  r.sinMu = area4 / (2 * b * c);
  const Real sin43 = s * r.sinMu;  // sin(θ4 − θ3)
  const Real e3x = std::cos(r.theta3), e3y = std::sin(r.theta3), e4x = std::cos(r.theta4), e4y = std::sin(r.theta4);
  r.omega3 = -a * w2 * (c2 * e4y - s2 * e4x) / (b * sin43);
  r.omega4 = -a * w2 * (c2 * e3y - s2 * e3x) / (c * sin43);
  const Real kx = a * (-al2 * s2 - w2 * w2 * c2) - b * r.omega3 * r.omega3 * e3x + c * r.omega4 * r.omega4 * e4x;
  const Real ky = a * (al2 * c2 - w2 * w2 * s2) - b * r.omega3 * r.omega3 * e3y + c * r.omega4 * r.omega4 * e4y;
  r.alpha3 = -(kx * e4x + ky * e4y) / (b * sin43);
  r.alpha4 = -(kx * e3x + ky * e3y) / (c * sin43);
  return r;
}

struct SliderReference {
  Real x = 0, xDot = 0, xDdot = 0, theta3 = 0;  // piston along the guide; rod angle
};

// Offset e, guide along +x, `sign` +1 for Branch::Open (the larger x).
SliderReference sliderCrank(const SliderCrankGeometry& g, double theta2, double omega2, double alpha2, int sign) {
  const Real a = g.crank, l = g.rod, e = g.offset, w2 = omega2, al2 = alpha2;
  const Real c2 = std::cos(static_cast<Real>(theta2)), s2 = std::sin(static_cast<Real>(theta2));
  const Real y = e - a * s2;  // C − B = (w, y)
  const Real w = sign * std::sqrt(std::max((l - std::abs(y)) * (l + std::abs(y)), Real(0)));
  const Real yDot = -a * w2 * c2, yDdot = -a * al2 * c2 + a * w2 * w2 * s2;
  const Real wDot = -y * yDot / w;  // from w² + y² = l²
  const Real wDdot = -(yDot * yDot + y * yDdot + wDot * wDot) / w;
  SliderReference r;
  r.x = a * c2 + w;
  r.xDot = -a * w2 * s2 + wDot;
  r.xDdot = -a * al2 * s2 - a * w2 * w2 * c2 + wDdot;
  r.theta3 = std::atan2(y, w);
  return r;
}

// --- Error bookkeeping -----------------------------------------------------------------------

// The largest error seen and the input angle where it occurred; NaN sticks.
struct Worst {
  double error = 0.0;
  double at = 0.0;
  void add(Real e, double angle) {
    if (std::isnan(error)) return;
    if (std::isnan(static_cast<double>(e)) || static_cast<double>(e) > error) {
      error = static_cast<double>(e);
      at = angle;
    }
  }
};

struct Errors {
  Worst position, angle, omega, alpha;
  int ok = 0, singular = 0;
  int misflagged = 0;  // Ok with the reference's sin μ under 0.9·kSingularSine, or Singular over 1.1×
};

// CHECKs a worst error against its bound, printing both (run with -s to see every value).
void checkBound(const Worst& w, double bound, const char* what) {
  INFO(what << ": error " << std::scientific << std::setprecision(2) << w.error << " at input angle "
            << std::setprecision(10) << w.at << " rad; bound " << std::setprecision(1) << bound);
  CHECK(w.error <= bound);
}

Mechanism makeFourBarOrFail(const FourBarLengths& l, Branch branch = Branch::Open) {
  const auto m = makeFourBar(l, branch);
  REQUIRE(m.ok());
  return *m;
}

double longest(const FourBarLengths& l) { return std::max({l.frame, l.crank, l.coupler, l.rocker}); }

// Which reference branch a sample should be on: +1, −1.
using SignAt = int (*)(const FourBarLengths&, double);
int open(const FourBarLengths&, double) { return 1; }
int crossed(const FourBarLengths&, double) { return -1; }

// How rate errors are scaled: by the larger of the crank's scale and the link's peak, or by the
// link's own peak alone (for a link that moves a million times slower than the crank).
enum class RateScale { Crank, OwnPeak };

// Compares every assembled sample of a four-bar sweep with the reference; rates only at Ok
// samples.
Errors compareSweep(const SweepResult& s, const FourBarLengths& l, const SweepSpec& spec, SignAt signAt = open,
                    RateScale rateScale = RateScale::Crank) {
  std::vector<FourBarReference> ref(s.size());
  const bool crank = rateScale == RateScale::Crank;
  const Real tiny = 1e-300;  // keeps 0/0 out when everything is exactly zero (ω2 = 0)
  const Real omegaScale = crank ? std::max(std::abs(Real(spec.omega)), tiny) : tiny;
  const Real alphaScale = crank ? std::max(Real(spec.omega) * spec.omega + std::abs(Real(spec.alpha)), tiny) : tiny;
  Real peak[4] = {omegaScale, omegaScale, alphaScale, alphaScale};
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.assembled(j)) continue;
    ref[j] = fourBar(l, s.inputAngle[j], spec.omega, spec.alpha, signAt(l, s.inputAngle[j]));
    if (!s.ok(j)) continue;
    peak[0] = std::max(peak[0], std::abs(ref[j].omega3));
    peak[1] = std::max(peak[1], std::abs(ref[j].omega4));
    peak[2] = std::max(peak[2], std::abs(ref[j].alpha3));
    peak[3] = std::max(peak[3], std::abs(ref[j].alpha4));
  }
  Errors e;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.assembled(j)) continue;
    const double at = s.inputAngle[j];
    const FourBarReference& r = ref[j];
    const Eigen::Vector2d& c = s.position[kC][j];
    e.position.add(std::hypot(c.x() - r.cx, c.y() - r.cy) / longest(l), at);
    e.angle.add(std::abs(std::remainder(s.linkAngle[kCoupler][j] - r.theta3, 2 * kPiL)), at);
    e.angle.add(std::abs(std::remainder(s.linkAngle[kRocker][j] - r.theta4, 2 * kPiL)), at);
    if (!s.ok(j)) {
      ++e.singular;
      if (r.sinMu > 1.1 * kSingularSine) ++e.misflagged;
      continue;
    }
    ++e.ok;
    if (r.sinMu < 0.9 * kSingularSine) ++e.misflagged;
    if (!s.request.velocities) continue;
    e.omega.add(std::abs(s.linkOmega[kCoupler][j] - r.omega3) / peak[0], at);
    e.omega.add(std::abs(s.linkOmega[kRocker][j] - r.omega4) / peak[1], at);
    if (!s.request.accelerations) continue;
    e.alpha.add(std::abs(s.linkAlpha[kCoupler][j] - r.alpha3) / peak[2], at);
    e.alpha.add(std::abs(s.linkAlpha[kRocker][j] - r.alpha4) / peak[3], at);
  }
  return e;
}

SweepResult sweepOrFail(const Mechanism& m, const SweepSpec& spec) {
  auto s = sweep(m, spec);
  REQUIRE(s.ok());
  CHECK(firstNonFinite(*s).empty());
  return std::move(s).value();
}

// A pose solved into a prepared Pose, so positions are available at a Singular report too.
struct Solved {
  PoseReport report;
  Pose pose;
};

Solved solveAt(const Mechanism& m, const DriverState& state) {
  Solved s;
  preparePose(m, s.pose);
  s.report = solvePoseInto(m, state, {true, true}, s.pose);
  return s;
}

Real relative(double value, Real reference) { return std::abs(value - reference) / std::abs(reference); }

}  // namespace

// --- Change points ----------------------------------------------------------------------------

namespace {

// The sign of the mode each change-point linkage keeps, from its explicit geometry.
// Parallelogram: C = B + (d, 0), so (C−B)×(C−O4) = d·a·sin θ.
int parallelogramSign(const FourBarLengths&, double theta) { return theta >= 0.0 ? 1 : -1; }
int antiparallelogramSign(const FourBarLengths&, double theta) { return theta >= 0.0 ? -1 : 1; }
// Kite (frame = rocker, crank = coupler): C is O2 mirrored in the line O4–B, on the side of
// O4→B opposite O2, which is right of B→O4 for θ in (0, π).
int kiteSign(const FourBarLengths&, double theta) { return theta >= 0.0 ? -1 : 1; }

// ±0.2 rad about the change point θ = 0 in steps of 1e-4 rad; sample 2000 is exactly 0.
constexpr SweepSpec kThroughZero{-0.2, 0.2, 4001, 1.0, 0.5};

}  // namespace

TEST_CASE(
    "Change points: parallelogram, antiparallelogram and kite keep their mode through θ = 0 — "
    "flagged only where sin μ < 1e-4 — 3e-4 rad away C to 5e-13, θ to 1e-12, ω to 5e-9, α to 2e-5",
    "[stability]") {
  struct Case {
    const char* name;
    FourBarLengths lengths;
    Branch branch;  // the branch that gives the mode at the first sample, θ = −0.2
    SignAt sign;
  };
  const Case c = GENERATE(values<Case>({
      {"parallelogram", {60.0, 25.0, 60.0, 25.0}, Branch::Crossed, parallelogramSign},
      {"antiparallelogram", {60.0, 25.0, 60.0, 25.0}, Branch::Open, antiparallelogramSign},
      {"kite", {60.0, 25.0, 25.0, 60.0}, Branch::Open, kiteSign},
  }));
  CAPTURE(c.name);
  REQUIRE(classifyGrashof(c.lengths).category == GrashofClass::ChangePoint);
  const SweepResult s = sweepOrFail(makeFourBarOrFail(c.lengths, c.branch), kThroughZero);
  CHECK(s.notAssembled.empty());
  // Flagged exactly where the reference's sin μ is under kSingularSine (1e-4), which here is
  // within 1e-4 rad of the change point: compareSweep counts any disagreement.
  CHECK(s.report[2000].status == PoseStatus::Singular);
  const Errors e = compareSweep(s, c.lengths, kThroughZero, c.sign);
  CAPTURE(e.position.at, e.omega.at, e.alpha.at);
  CHECK(e.misflagged == 0);
  // The mode is kept: the position matches the mode's own reference everywhere. The worst
  // errors sit at the Ok samples just outside the flagged ones (2e-4 to 3e-4 rad away):
  // positions go like ε/sin μ (1.8e-13 of the longest link reached), ω like ε/sin²μ (1.4e-9
  // of scale), α like ε/sin³μ (6.4e-6 of scale).
  checkBound(e.position, 5e-13, "C");
  checkBound(e.angle, 1e-12, "θ3, θ4");
  checkBound(e.omega, 5e-9, "ω3, ω4");
  checkBound(e.alpha, 2e-5, "α3, α4");
  // Even a two-sample sweep straight across the change point, ±δ, ends in the same mode: the
  // tracker halves the step down to 1e-7 rad and extrapolates (sweep.h). The two candidates
  // are only ~δ·length apart there, so the test is which one C is nearer. At δ = 1e-9 the
  // modes are 9e-8 apart but the diagonal's distance from its limit (~1e-17) is below its
  // rounding (ε·35 ≈ 8e-15), so the core puts C midway (h = 0): 5e-8 from either, the most
  // double precision can say there.
  for (const double delta : {1e-3, 1e-5, 1e-7, 1e-9}) {
    CAPTURE(delta);
    const SweepResult two = sweepOrFail(makeFourBarOrFail(c.lengths, c.branch), {-delta, delta, 2, 1.0, 0.0});
    const int sign = c.sign(c.lengths, delta);
    const FourBarReference mode = fourBar(c.lengths, delta, 1.0, 0.0, sign);
    const FourBarReference other = fourBar(c.lengths, delta, 1.0, 0.0, -sign);
    const Eigen::Vector2d& end = two.position[kC][1];
    const Real toMode = std::hypot(end.x() - mode.cx, end.y() - mode.cy);
    if (delta >= 1e-7) CHECK(toMode < std::hypot(end.x() - other.cx, end.y() - other.cy));
    else CHECK(toMode <= 1e-7);
  }
}

TEST_CASE(
    "A deltoid's coincident point B ≡ O4 is a one-sample gap — the sweep restarts on the "
    "mechanism's branch (a jump) — 3e-4 rad away C to 5e-13, ω to 2e-9, α to 1e-5",
    "[stability]") {
  // Frame = crank = 25, coupler = rocker = 60: at θ = 0 the crank tip lies on O4 and C is
  // undetermined (any point of the circle of radius 60 about O4). The geometric continuation
  // through θ = 0 keeps C on the bisector ray at angle θ/2, which for B→O4 turning over means
  // switching from Open to Crossed; the sweep instead reports the coincident sample as not
  // assemblable and restarts on Branch::Open, so C jumps from (−35, 0) to (85, 0). This is the
  // documented limit (docs/accuracy.md): the output is exact on each side, and the gap says
  // where the mode was lost.
  const FourBarLengths l{25.0, 25.0, 60.0, 60.0};
  REQUIRE(classifyGrashof(l).category == GrashofClass::ChangePoint);
  const SweepResult s = sweepOrFail(makeFourBarOrFail(l), kThroughZero);
  REQUIRE(s.notAssembled.size() == 1);
  CHECK(s.notAssembled[0] == AngleRange{0.0, 0.0});
  CHECK(s.report[2000].failure == AssemblyFailure::Coincident);
  REQUIRE(s.firstFailure.has_value());
  CHECK(s.firstFailure->find("coincide") != std::string::npos);
  CHECK(s.position[kC][1999].x() == Approx(-35.0).margin(1e-3));
  CHECK(s.position[kC][2001].x() == Approx(85.0).margin(1e-3));
  const Errors e = compareSweep(s, l, kThroughZero);
  // Next to B ≡ O4 the coupler and rocker (both 60) are nearly parallel, sin μ ≈ |BO4|/60:
  // flagged within 2e-4 rad.
  CHECK(e.misflagged == 0);
  // Reached: C 2.0e-13, θ 2.0e-13, ω 6.7e-10, α 3.0e-6, all next to the flagged samples.
  checkBound(e.position, 5e-13, "C");
  checkBound(e.angle, 5e-13, "θ3, θ4");
  checkBound(e.omega, 2e-9, "ω3, ω4");
  checkBound(e.alpha, 1e-5, "α3, α4");
}

// --- Non-Grashof toggles ----------------------------------------------------------------------

TEST_CASE(
    "A triple-rocker's toggle approached to δ = 1e-9 rad: θ3, θ4 within ε/√δ (7e-14 at 1e-9) — "
    "ω within 2ε/δ and α within 5ε/δ relative while Ok (δ ≥ 1e-8, sin μ ≥ 2e-4) — flagged at 1e-9",
    "[stability]") {
  const FourBarLengths l{40.0, 30.0, 20.0, 25.0};
  REQUIRE(classifyGrashof(l).category == GrashofClass::TripleRocker);
  const InputRange range = fourBarInputRange(l);
  REQUIRE(range.ranges.size() == 1);
  const double toggle = range.ranges[0].to;  // BO4 = coupler + rocker: extended
  const Mechanism m = makeFourBarOrFail(l);
  const double omega2 = 2.0, alpha2 = -3.0;
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double lastScaledOmega = 0.0;
  for (int k = 1; k <= 9; ++k) {
    const double delta = std::pow(10.0, -k);
    const double theta = toggle - delta;
    const Solved p = solveAt(m, {theta, omega2, alpha2});
    const FourBarReference r = fourBar(l, theta, omega2, alpha2, 1);
    INFO("δ = " << delta << ", reference sin μ = " << static_cast<double>(r.sinMu));
    REQUIRE(p.report.status != PoseStatus::NotAssemblable);
    // sin μ ∝ √δ, and the dyad's h = √(gap·…) turns the gap's ε round-off into ε/√δ of angle;
    // the rates divide by sin²μ ∝ δ once more (measured constants 0.8, 0.7 and 2.3).
    Worst angle, omega, alpha;
    angle.add(std::abs(p.pose.linkAngle[kRocker] - static_cast<double>(r.theta4)), theta);
    angle.add(std::abs(p.pose.linkAngle[kCoupler] - static_cast<double>(r.theta3)), theta);
    checkBound(angle, kEps / std::sqrt(delta), "θ3, θ4");
    CHECK((p.report.status == PoseStatus::Ok) == (r.sinMu > kSingularSine));
    if (p.report.status != PoseStatus::Ok) continue;
    omega.add(relative(p.pose.linkOmega[kRocker], r.omega4), theta);
    omega.add(relative(p.pose.linkOmega[kCoupler], r.omega3), theta);
    alpha.add(relative(p.pose.linkAlpha[kRocker], r.alpha4), theta);
    alpha.add(relative(p.pose.linkAlpha[kCoupler], r.alpha3), theta);
    checkBound(omega, 2.0 * kEps / delta, "ω3, ω4 relative");
    checkBound(alpha, 5.0 * kEps / delta, "α3, α4 relative");
    // ω grows like 1/√δ: ω·√δ settles to a constant as the toggle nears.
    const double scaled = p.pose.linkOmega[kRocker] * std::sqrt(delta);
    if (k >= 5) CHECK(scaled == Approx(lastScaledOmega).epsilon(0.01));
    lastScaledOmega = scaled;
  }
  // A sweep ending exactly on the toggle flags that sample and nothing else.
  const SweepSpec spec{toggle - 0.5, toggle, 5001, omega2, alpha2};
  const SweepResult s = sweepOrFail(m, spec);
  CHECK(s.notAssembled.empty());
  CHECK(s.singularAngles == std::vector<double>{toggle});
  const Errors e = compareSweep(s, l, spec);
  CHECK(e.misflagged == 0);
  // Reached: C 1.3e-15, θ 2.6e-15, ω 4.3e-14, α 8.9e-14 of the peaks (the toggle sample itself
  // happens to round onto the limit, so its position is exact).
  checkBound(e.position, 5e-15, "C");
  checkBound(e.angle, 1e-14, "θ3, θ4");
  checkBound(e.omega, 1e-13, "ω3, ω4");
  checkBound(e.alpha, 2e-13, "α3, α4");
}

// --- Transmission angle near 0° and 180° -------------------------------------------------------

TEST_CASE(
    "Crank-rockers whose transmission angle comes within m = 1e-2, 1e-3, 1e-5 of 0° or 180°: "
    "ω to 2e-12, 2e-10, 5e-11 and α to 5e-12, 5e-10, 5e-8 of the peak — sin μ < 1e-4 flagged",
    "[stability]") {
  struct Case {
    double margin;      // rad: the extreme transmission angle is m (at θ = 0) or π − m (at θ = π)
    bool nearStraight;  // true: π − m; false: m
    double positionBound, angleBound, omegaBound, alphaBound;  // reached, rounded up past 2×
  };
  const Case c = GENERATE(values<Case>({
      {1e-2, false, 1e-14, 1e-14, 5e-14, 2e-13},  // reached 3.7e-15, 4.3e-15, 1.8e-14, 6.1e-14
      {1e-2, true, 5e-14, 5e-14, 2e-12, 5e-12},   // 1.2e-14, 2.1e-14, 7.6e-13, 1.3e-12
      {1e-3, false, 5e-14, 5e-14, 2e-12, 2e-12},  // 1.8e-14, 2.1e-14, 8.2e-13, 8.3e-13
      {1e-3, true, 2e-13, 5e-13, 2e-10, 5e-10},   // 9.2e-14, 1.7e-13, 5.9e-11, 1.0e-10
      {1e-5, false, 1e-13, 1e-13, 2e-11, 1e-8},   // 3.9e-14, 4.6e-14, 5.6e-12, 4.7e-9
      {1e-5, true, 1e-13, 2e-13, 5e-11, 5e-8},    // 4.6e-14, 8.4e-14, 2.4e-11, 1.0e-8
  }));
  CAPTURE(c.margin, c.nearStraight);
  // Coupler 60, rocker 70, crank 20; the frame puts |BO4| at the wanted diagonal: d − a at
  // θ = 0 for μ = m, d + a at θ = π for μ = π − m.
  const double b = 60.0, cr = 70.0, a = 20.0;
  const double mu = c.nearStraight ? kPi - c.margin : c.margin;
  const double diagonal = std::sqrt(b * b + cr * cr - 2.0 * b * cr * std::cos(mu));
  const FourBarLengths l{c.nearStraight ? diagonal - a : diagonal + a, a, b, cr};
  const InputRange range = fourBarInputRange(l);
  REQUIRE(range.fullRotation);
  const SweepSpec spec{0.0, 2.0 * kPi, 3601, 10.0, 40.0};  // samples 0 and 1800: θ = 0 and π
  const SweepResult s = sweepOrFail(makeFourBarOrFail(l), spec);
  CHECK(s.notAssembled.empty());
  const Errors e = compareSweep(s, l, spec);
  CAPTURE(e.omega.at, e.alpha.at);
  checkBound(e.position, c.positionBound, "C");
  checkBound(e.angle, c.angleBound, "θ3, θ4");
  checkBound(e.omega, c.omegaBound, "ω3, ω4");
  checkBound(e.alpha, c.alphaBound, "α3, α4");
  // Only the extreme is flagged (θ = 0 is sampled twice, as 0 and 2π), and only when its
  // sine is under the threshold.
  CHECK(e.misflagged == 0);
  CHECK((e.singular > 0) == (c.margin < kSingularSine));
}

// --- Length ratios and absolute scales ---------------------------------------------------------

TEST_CASE(
    "Length ratios 1e-6 to 1e6: positions to 1e-15 of the longest link — the angle and rates of "
    "a link ℓ long at D from the origin to about ε·D/ℓ (2e-10 at D/ℓ = 1e6)",
    "[stability]") {
  // Rates over each link's own peak: the rocker of the first case moves a millionth as fast
  // as the crank, and its ω is checked to its own digits. With the frame 1e6 long, the short
  // coupler (or rocker) sits 1e6 from the origin, where coordinates are spaced ε·1e6 ≈ 1e-10
  // apart, so its angle cannot be better than that over its length: a limit of absolute
  // coordinates, not of the dyad solution.
  struct Case {
    const char* name;
    FourBarLengths lengths;
    double positionBound, angleBound, omegaBound, alphaBound;  // reached, rounded up past 2×
  };
  // Reached (C, θ, ω, α): 3.7e-16 4.2e-16 4.7e-16 5.3e-16; 3.6e-16 3.9e-16 4.9e-16 6.5e-16;
  // 3.9e-16 1.3e-15 5.0e-16 4.1e-15; 1.7e-16 8.4e-14 7.2e-14 6.8e-14; 1.7e-16 8.6e-11 7.2e-11
  // 7.4e-11; 2.7e-16 1.3e-10 1.2e-10 8.5e-11.
  const Case c = GENERATE(values<Case>({
      {"crank 1e-6 of the others", {1.0, 1e-6, 1.0, 1.0}, 1e-15, 1e-15, 1e-15, 2e-15},
      {"crank 1e-3 of the others", {1.0, 1e-3, 1.0, 1.0}, 1e-15, 2e-15, 1e-15, 2e-15},
      {"frame 1e-6 of the others (drag link)", {1e-6, 1.0, 1.0, 1.0}, 1e-15, 5e-15, 2e-15, 1e-14},
      {"frame and rocker 1e3 × crank", {1e3, 1.0, 2.0, 1e3}, 1e-15, 2e-13, 2e-13, 2e-13},
      {"frame and rocker 1e6 × crank", {1e6, 1.0, 2.0, 1e6}, 1e-15, 2e-10, 2e-10, 2e-10},
      {"frame and coupler 1e6 × crank", {1e6, 1.0, 1e6, 2.0}, 1e-15, 5e-10, 5e-10, 2e-10},
  }));
  CAPTURE(c.name);
  const InputRange range = fourBarInputRange(c.lengths);
  REQUIRE(!range.ranges.empty());
  const AngleRange r = range.ranges[0];
  const double inset = range.fullRotation ? 0.0 : 1e-3 * (r.to - r.from);
  const SweepSpec spec{r.from + inset, r.to - inset, 1441, 3.0, -2.0};
  const SweepResult s = sweepOrFail(makeFourBarOrFail(c.lengths), spec);
  CHECK(s.notAssembled.empty());
  CHECK(s.singularAngles.empty());
  const Errors e = compareSweep(s, c.lengths, spec, open, RateScale::OwnPeak);
  checkBound(e.position, c.positionBound, "C");
  checkBound(e.angle, c.angleBound, "θ3, θ4");
  checkBound(e.omega, c.omegaBound, "ω3, ω4");
  checkBound(e.alpha, c.alphaBound, "α3, α4");
}

TEST_CASE(
    "Coupler and rocker 1e6 × crank and frame: sin μ ≤ 1e-6 everywhere, so every sample is "
    "flagged — positions still to 5e-14 of the longest link",
    "[stability]") {
  // C lies a million lengths away and the coupler and rocker are nearly parallel: the rates
  // exist but are never reported (a limit, docs/accuracy.md).
  // Coupler 1e6 and rocker 1e6 − 0.5 (not 1e6 + 0.5 and 1e6): the same half-unit difference, within
  // the input domain's length ratio of 1e6 (validate.h).
  const FourBarLengths l{1.0, 1.0, 1e6, 1e6 - 0.5};
  const SweepSpec spec{0.6, kPi, 721, 1.0, 0.0};
  const SweepResult s = sweepOrFail(makeFourBarOrFail(l), spec);
  CHECK(s.notAssembled.empty());
  CHECK(s.singularAngles.size() == s.size());
  const Errors e = compareSweep(s, l, spec);
  // Reached 1.5e-14 for both: C 1e6 away on two nearly parallel links.
  checkBound(e.position, 5e-14, "C");
  checkBound(e.angle, 5e-14, "θ3, θ4");
}

TEST_CASE(
    "Absolute scales 1e-6 to 1e6: the thesis four-bar and the LS3 slider-crank to the same "
    "relative accuracy at every scale (positions to 1e-15, angles, ω and α to 5e-15 of scale)",
    "[stability]") {
  const double scale = GENERATE(1e-6, 1e-3, 1.0, 1e3, 1e6);
  CAPTURE(scale);
  const FourBarLengths l{kThesis.frame * scale, kThesis.crank * scale, kThesis.coupler * scale, kThesis.rocker * scale};
  const SweepSpec spec{0.0, 2.0 * kPi, 721, 1.2, 0.5};
  for (const Branch branch : {Branch::Open, Branch::Crossed}) {
    const SweepResult s = sweepOrFail(makeFourBarOrFail(l, branch), spec);
    const Errors e = compareSweep(s, l, spec, branch == Branch::Open ? open : crossed);
    CAPTURE(branch == Branch::Open);
    CHECK(e.singular == 0);
    // Reached at every scale and branch: C 4.7e-16, θ 6.9e-16, ω 6.9e-16, α 1.1e-15.
    checkBound(e.position, 1e-15, "C");
    checkBound(e.angle, 2e-15, "θ3, θ4");
    checkBound(e.omega, 2e-15, "ω3, ω4");
    checkBound(e.alpha, 5e-15, "α3, α4");
  }
  const SliderCrankGeometry g{kLs3Engine.crank * scale, kLs3Engine.rod * scale, 0.0, false};
  const auto m = makeSliderCrank(g);
  REQUIRE(m.ok());
  const SweepResult s = sweepOrFail(*m, spec);
  CHECK(s.singularAngles.empty());
  Worst x, v, acc, angle;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const SliderReference r = sliderCrank(g, s.inputAngle[j], spec.omega, spec.alpha, 1);
    const double at = s.inputAngle[j];
    x.add(std::abs(s.position[slidercrank::kC.index][j].x() - r.x) / g.rod, at);
    v.add(std::abs(s.velocity[slidercrank::kC.index][j].x() - r.xDot) / (g.crank * spec.omega), at);
    acc.add(std::abs(s.acceleration[slidercrank::kC.index][j].x() - r.xDdot) / (g.crank * spec.omega * spec.omega), at);
    angle.add(std::abs(s.linkAngle[slidercrank::kRod.index][j] - r.theta3), at);
  }
  // Reached: x 2.4e-16 of the rod, ẋ 3.2e-16 of a·ω2, ẍ 4.7e-16 of a·ω2², rod angle 9.2e-17.
  checkBound(x, 1e-15, "piston x");
  checkBound(v, 1e-15, "piston ẋ");
  checkBound(acc, 1e-15, "piston ẍ");
  checkBound(angle, 5e-16, "rod angle");
}

// --- High speed --------------------------------------------------------------------------------

TEST_CASE(
    "ω2 = 1e5 rad/s with α2 ≠ 0: ω to 1e-15 of ω2, α to 2e-15 of ω2² + |α2| (the piston's ẍ "
    "to 1e-15), linear in α2 and quadratic in ω2 to round-off",
    "[stability]") {
  struct Case {
    double omega, alpha;
  };
  const Case c = GENERATE(values<Case>({{1e5, 0.0}, {1e5, 1e10}, {1e5, -3e9}, {0.0, 1e9}, {-1e5, 7e8}}));
  CAPTURE(c.omega, c.alpha);
  const SweepSpec spec{0.0, 2.0 * kPi, 361, c.omega, c.alpha};
  const SweepResult s = sweepOrFail(makeFourBarOrFail(kThesis), spec);
  const Errors e = compareSweep(s, kThesis, spec);
  CHECK(e.singular == 0);
  // Reached: ω 4.5e-16, α 9.0e-16, piston ẍ 3.9e-16.
  checkBound(e.omega, 1e-15, "ω3, ω4");
  checkBound(e.alpha, 2e-15, "α3, α4");
  // α = K(θ)·α2 + K'(θ)·ω2²: the sweeps at (ω2, 0) and (0, α2) add up to this one.
  const SweepResult spin = sweepOrFail(makeFourBarOrFail(kThesis), {0.0, 2.0 * kPi, 361, c.omega, 0.0});
  const SweepResult push = sweepOrFail(makeFourBarOrFail(kThesis), {0.0, 2.0 * kPi, 361, 0.0, c.alpha});
  const double scale = c.omega * c.omega + std::abs(c.alpha);
  for (std::size_t j = 0; j < s.size(); ++j)
    for (const std::size_t k : {kCoupler, kRocker})
      CHECK(s.linkAlpha[k][j] == linkwright::test::within(spin.linkAlpha[k][j] + push.linkAlpha[k][j], 1e-14 * scale));
  // The slider-crank: the piston's acceleration against its closed form.
  const auto m = makeSliderCrank(kLs3Engine);
  REQUIRE(m.ok());
  const SweepResult piston = sweepOrFail(*m, spec);
  Worst acc;
  for (std::size_t j = 0; j < piston.size(); ++j) {
    const SliderReference r = sliderCrank(kLs3Engine, piston.inputAngle[j], c.omega, c.alpha, 1);
    acc.add(std::abs(piston.acceleration[slidercrank::kC.index][j].x() - r.xDdot) / (kLs3Engine.crank * scale),
            piston.inputAngle[j]);
  }
  checkBound(acc, 1e-15, "piston ẍ");
}

// --- Slivers -----------------------------------------------------------------------------------

TEST_CASE(
    "Linkages assemblable on ~1e-3 rad of input: the sweep's gaps match the exact range "
    "to one step (plus 3e-7 rad of assembly tolerance) — angles to 2e-12 inside, √(ε·L/ℓ) on a toggle",
    "[stability]") {
  // Errors reached, rounded up past 2×. Over the whole turn the samples fall at most a step
  // (3e-5 rad) inside an edge; a sweep of exactly one sliver has its first and last samples on
  // the toggles, where a rounding of the diagonal L by ε·L moves the short link ℓ by √(ε·L·ℓ),
  // i.e. its angle by √(ε·L/ℓ): 1e-6 rad for the 3.5e-4 rocker (9.6e-7 reached). That is the
  // problem's square-root sensitivity at a toggle, not the solver's.
  struct Case {
    const char* name;
    FourBarLengths lengths;
    double positionBound;
    double angleBound, omegaBound, alphaBound;  // whole turn
    double edgeAngle, edgeOmega, edgeAlpha;     // one sliver, ends on the toggles
  };
  const Case c = GENERATE(values<Case>({
      // Tiny rocker: |BO4| must stay within b ± c, two slivers about ±90°; inside them the
      // rocker turns a full circle (ω4 ≈ 6000·ω2). Reached: C 4.2e-16; θ 1.7e-12 (the rocker
      // is 4000 times shorter than its distance from the origin), ω 3.3e-12, α 1.1e-11; one
      // sliver: θ 9.6e-7, ω 1.3e-10, α 4.0e-10.
      {"tiny rocker, slivers at ±90°",
       {1.0, 1.0, std::sqrt(2.0), 3.5355339059327378e-4},
       1e-15,
       5e-12,
       1e-11,
       5e-11,
       2e-6,
       5e-10,
       1e-9},
      // Triple-rocker at its extended toggle: one sliver |θ| ≤ 5e-4 rad, sin μ ≤ 9e-4 inside.
      // Reached: C 1.7e-13, θ 5.1e-13, ω 2.2e-9, α 7.3e-9; one sliver: θ 2.9e-12, ω 2.6e-8,
      // α 5.6e-8 (next to the flagged ends).
      {"triple-rocker, sliver about 0", {3.0, 1.0, 1.0, 1.0 + 1.875e-7}, 5e-13, 2e-12, 5e-9, 2e-8, 1e-11, 1e-7, 2e-7},
  }));
  CAPTURE(c.name);
  const InputRange range = fourBarInputRange(c.lengths);
  REQUIRE(!range.fullRotation);
  for (const AngleRange& r : range.ranges) CHECK(r.to - r.from == Approx(1e-3).epsilon(0.01));
  const Mechanism m = makeFourBarOrFail(c.lengths);
  const std::size_t samples = 200001;
  const SweepSpec wide{-kPi, kPi, samples, 1.0, 0.5};
  const SweepResult s = sweepOrFail(m, wide);
  const double step = 2.0 * kPi / static_cast<double>(samples - 1);
  // Every sample is where the exact range says, but for the assembly tolerance: a diagonal
  // past its limit by under 1e-10 of coupler + rocker is taken as at it, which moves an edge
  // by up to 1e-10·(b + c)/|d|BO4|/dθ| (2.7e-7 rad for the triple-rocker).
  constexpr double kEdgeSlack = 3e-7;
  std::size_t assembled = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double at = s.inputAngle[j];
    CAPTURE(j, at);
    if (s.assembled(j)) {
      ++assembled;
      CHECK(range.contains(at, kEdgeSlack));
    } else {
      CHECK_FALSE(range.contains(at, 0.0));
    }
  }
  CHECK(assembled >= range.ranges.size() * 30);
  // The gaps are the complement of the range, each ending within a step of an edge.
  std::vector<AngleRange> sorted = range.ranges;
  std::sort(sorted.begin(), sorted.end(), [](const AngleRange& x, const AngleRange& y) { return x.from < y.from; });
  REQUIRE(s.notAssembled.size() == sorted.size() + 1);
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    CHECK(sorted[k].from - s.notAssembled[k].to <= step);
    CHECK(s.notAssembled[k + 1].from - sorted[k].to <= step);
  }
  const Errors e = compareSweep(s, c.lengths, wide);
  CHECK(e.misflagged == 0);
  checkBound(e.position, c.positionBound, "C");
  checkBound(e.angle, c.angleBound, "θ3, θ4");
  checkBound(e.omega, c.omegaBound, "ω3, ω4");
  checkBound(e.alpha, c.alphaBound, "α3, α4");
  // Sweeping exactly one sliver: both ends are toggles (flagged), the rest is Ok.
  const AngleRange r = range.ranges[0];
  const SweepSpec narrow{r.from, r.to, 1001, 1.0, 0.5};
  const SweepResult n = sweepOrFail(m, narrow);
  CHECK(n.notAssembled.empty());
  CHECK(n.report.front().status == PoseStatus::Singular);
  CHECK(n.report.back().status == PoseStatus::Singular);
  const Errors en = compareSweep(n, c.lengths, narrow);
  CHECK(en.misflagged == 0);
  checkBound(en.angle, c.edgeAngle, "θ3, θ4 (one sliver)");
  checkBound(en.omega, c.edgeOmega, "ω3, ω4 (one sliver)");
  checkBound(en.alpha, c.edgeAlpha, "α3, α4 (one sliver)");
}

// --- Slider-crank ------------------------------------------------------------------------------

TEST_CASE(
    "Slider-crank with rod/crank from 1 + 1e-9 to 1e6: piston x to 2e-14 of the crank (5e-10 "
    "at 1e6), ẋ to 5e-12, ẍ to 2e-12 — flagged only at 1 + 1e-9",
    "[stability]") {
  // Near rod = crank the rod stands almost across the guide at θ = 90°: r·u/|r| = √(2η) for
  // rod = crank·(1 + η), under kSingularSine only for η < 5e-9. At rod = 1e6·crank the piston
  // sits 1e6 from the origin, where x is spaced 1.2e-10 apart.
  struct Case {
    double ratio;                   // rod / crank
    double xBound, vBound, aBound;  // x over the crank, ẋ over a·ω2, ẍ over the peak |ẍ|
  };
  const Case c = GENERATE(values<Case>({
      {1e6, 5e-10, 1e-15, 1e-15},         // reached 1.4e-10, 2.1e-16, 3.2e-16
      {4.0, 2e-15, 1e-15, 1e-15},         // 9.8e-16, 2.1e-16, 3.5e-16
      {1.0 + 1e-2, 1e-15, 5e-15, 1e-14},  // 3.7e-16, 1.3e-15, 2.7e-15
      {1.0 + 1e-4, 1e-14, 2e-13, 5e-13},  // 3.2e-15, 9.0e-14, 1.3e-13
      {1.0 + 1e-6, 2e-14, 5e-12, 2e-12},  // 8.9e-15, 1.6e-12, 7.7e-13
      {1.0 + 1e-8, 2e-14, 5e-12, 1e-12},  // 9.2e-15, 2.2e-12, 3.5e-13
      {1.0 + 1e-9, 2e-14, 5e-12, 1e-12},
  }));
  CAPTURE(c.ratio);
  const SliderCrankGeometry g{1.0, c.ratio, 0.0, false};
  const auto m = makeSliderCrank(g);
  REQUIRE(m.ok());
  const SweepSpec spec{0.0, 2.0 * kPi, 3601, 2.0, 1.0};  // sample 900 at 90°, the near-toggle
  const SweepResult s = sweepOrFail(*m, spec);
  CHECK(s.notAssembled.empty());
  std::vector<SliderReference> ref(s.size());
  Real peak = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    ref[j] = sliderCrank(g, s.inputAngle[j], spec.omega, spec.alpha, 1);
    peak = std::max(peak, std::abs(ref[j].xDdot));
  }
  Worst x, v, acc;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double at = s.inputAngle[j];
    x.add(std::abs(s.position[slidercrank::kC.index][j].x() - ref[j].x) / g.crank, at);
    if (!s.ok(j)) continue;
    v.add(std::abs(s.velocity[slidercrank::kC.index][j].x() - ref[j].xDot) / (g.crank * spec.omega), at);
    acc.add(std::abs(s.acceleration[slidercrank::kC.index][j].x() - ref[j].xDdot) / peak, at);
  }
  CAPTURE(v.at, acc.at);
  checkBound(x, c.xBound, "piston x");
  checkBound(v, c.vBound, "piston ẋ");
  checkBound(acc, c.aBound, "piston ẍ");
  CHECK(s.singularAngles.size() == (c.ratio - 1.0 < 5e-9 ? 2u : 0u));  // θ = 90° and 270°
}

TEST_CASE(
    "Slider-crank with rod = crank: the piston keeps x = 2a·cos θ through the toggle at 90°, "
    "flagged there — x to 2e-14, ẋ to 5e-12 of a·ω2 elsewhere",
    "[stability]") {
  // With rod = crank and no offset the two branches cross at θ = 90° (x = 2a·cos θ and x = 0):
  // a change point of the slider-crank. Starting on Open (x = 2a·cos θ for cos θ > 0), the
  // tracker keeps that mode: x stays 2a·cos θ past 90°, i.e. it switches to Crossed there.
  const SliderCrankGeometry g{1.0, 1.0, 0.0, false};
  const auto m = makeSliderCrank(g);
  REQUIRE(m.ok());
  const SweepSpec spec{0.0, kPi, 1801, 2.0, 1.0};  // sample 900 at 90°
  const SweepResult s = sweepOrFail(*m, spec);
  CHECK(s.notAssembled.empty());
  CHECK(s.singularAngles.size() == 1);
  CHECK(s.report[900].status == PoseStatus::Singular);
  Worst x, v;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const double theta = s.inputAngle[j];
    x.add(std::abs(s.position[slidercrank::kC.index][j].x() - 2.0 * std::cos(theta)), theta);
    if (!s.ok(j)) continue;
    const double exactVelocity = -2.0 * spec.omega * std::sin(theta);  // d/dt of 2a·cos θ, a = 1
    v.add(std::abs(s.velocity[slidercrank::kC.index][j].x() - exactVelocity) / spec.omega, theta);
  }
  CAPTURE(x.at, v.at);
  // Reached: x 9.2e-15, ẋ 2.1e-12, both next to the flagged sample.
  checkBound(x, 2e-14, "piston x");
  checkBound(v, 5e-12, "piston ẋ");
}
