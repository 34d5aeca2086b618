// The atlas's classification (kinematics/analysis/coupler_curve_features.h) does not depend on
// the samples: on constructed curves each feature is found at 360 and at 1440 samples, at the
// same place to the tolerance classifierTolerances() states, and where the place is known in
// closed form, there:
// - a cusp built at the coupler's instant centre I13 (P on the fixed centrode's partner: the
//   point at rest) at crank angle 1 rad;
// - a figure-eight's crunode, which the solver's P passes at both crank angles found;
// - Norton's symmetric curve (coupler = rocker, |CP| = |BC|), whose mirror line passes through
//   the rocker pivot O4;
// - Hoeken's straight run, and P at B's circle of radius 1 about O2.

#include "kinematics/analysis/coupler_curve_features.h"

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/catch.h"
#include "tests/support/coupler_curves.h"

#include <cmath>

using namespace linkwright::kinematics;
namespace test = linkwright::test;

namespace {

double angleGap(double a, double b) { return std::abs(std::remainder(a - b, 2.0 * kPi)); }

struct Both {
  CurveFeatures coarse, fine;  // at 360 and 1440 samples
};

Both classified(const FourBarLengths& l, CouplerPointSpec p) {
  return {classifyCouplerCurve(test::couplerCurveOf(l, p, 360)),
          classifyCouplerCurve(test::couplerCurveOf(l, p, 1440))};
}

// The features found, by name and count: what must not change with the samples.
std::vector<std::size_t> verdict(const CurveFeatures& f) {
  return {f.cusps.size(), f.crunodes.size(), f.symmetry ? 1u : 0u, f.straight ? 1u : 0u, f.circular ? 1u : 0u};
}

}  // namespace

TEST_CASE("classifier tolerances are the rules' and scale below 360 samples", "[atlas]") {
  const ClassifierTolerances t = classifierTolerances(360);
  CHECK(t.cuspSpeed == kCuspSpeed);
  CHECK(t.symmetry == kSymmetryTolerance);
  CHECK(t.straight == kStraightTolerance);
  CHECK(t.circular == kCircularTolerance);
  CHECK(t.crossingAngleDeg == Approx(0.573).epsilon(1e-3));
  CHECK(t.arcTurnDeg == Approx(60.0));
  CHECK(t.runEnd == Approx(kPi / 180.0));
  CHECK(classifierTolerances(1440).cuspPoint == t.cuspPoint);
  CHECK(classifierTolerances(180).cuspPoint == Approx(16.0 * t.cuspPoint));
}

TEST_CASE("a constructed cusp is found at both sample counts, at its angle and point", "[atlas][cusp]") {
  const FourBarLengths l{3.0, 1.0, 3.0, 2.5};
  const double angle = 1.0;
  const auto bare = makeFourBar(l, Branch::Open);
  REQUIRE(bare.ok());
  const auto pose = solvePose(*bare, {angle, 1.0, 0.0});
  REQUIRE(pose.ok());
  const Eigen::Vector2d b = pose->position[fourbar::kB.index], c = pose->position[fourbar::kC.index];
  const auto centres =
      fourBarInstantCentres(pose->position[fourbar::kO2.index], pose->position[fourbar::kO4.index], b, c);
  REQUIRE(centres.ok());
  const Eigen::Vector2d i13 = centres->centre(1, 3).position;
  const Eigen::Vector2d u = (c - b).normalized(), n(-u.y(), u.x());
  const Both f = classified(l, {(i13 - b).dot(u), (i13 - b).dot(n)});
  REQUIRE(verdict(f.coarse) == verdict(f.fine));
  REQUIRE(f.coarse.cusps.size() == 1);
  const ClassifierTolerances t = classifierTolerances(360);
  for (const CurveFeatures* g : {&f.coarse, &f.fine}) {
    const Cusp& cusp = g->cusps.front();
    CAPTURE(cusp.crankAngle - angle, (cusp.point - i13).norm() / g->size);
    CHECK(angleGap(cusp.crankAngle, angle) <= t.cuspAngle);
    CHECK((cusp.point - i13).norm() <= t.cuspPoint * g->size);
    CHECK(cusp.speed <= t.cuspSpeed * g->size);
  }
}

TEST_CASE("a figure-eight's crunode is found at both sample counts, where P passes twice", "[atlas][crunode]") {
  const FourBarLengths l{2.5, 1.0, 1.5, 2.5};
  const CouplerPointSpec p{2.25, 1.5};
  const Both f = classified(l, p);
  REQUIRE(verdict(f.coarse) == verdict(f.fine));
  REQUIRE(f.coarse.crunodes.size() == 1);
  const ClassifierTolerances t = classifierTolerances(360);
  const Crunode &a = f.coarse.crunodes.front(), &b = f.fine.crunodes.front();
  CAPTURE((a.point - b.point).norm() / f.fine.size, a.crankAngles[0] - b.crankAngles[0],
          a.crankAngles[1] - b.crankAngles[1]);
  CHECK((a.point - b.point).norm() <= t.crunodePoint * f.fine.size);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(angleGap(a.crankAngles[k], b.crankAngles[k]) <= t.crunodeAngle);
    for (const Crunode* x : {&a, &b})
      CHECK((test::couplerPointAt(l, p, x->crankAngles[k]) - x->point).norm() <= t.crunodePoint * f.fine.size);
  }
}

TEST_CASE("Norton's symmetric curve has the same mirror line at both sample counts", "[atlas][symmetric]") {
  const FourBarLengths l{3.0, 1.0, 2.5, 2.5};
  const double gamma = 1.6;
  const Both f = classified(l, {2.5 + 2.5 * std::cos(gamma), 2.5 * std::sin(gamma)});
  REQUIRE(verdict(f.coarse) == verdict(f.fine));
  REQUIRE(f.coarse.symmetry.has_value());
  const ClassifierTolerances t = classifierTolerances(360);
  const SymmetryAxis &a = *f.coarse.symmetry, &b = *f.fine.symmetry;
  const double turn =
      std::asin(std::min(1.0, std::abs(a.direction.x() * b.direction.y() - a.direction.y() * b.direction.x())));
  CAPTURE(turn, a.deviation / f.coarse.size, b.deviation / f.fine.size);
  CHECK(turn <= t.symmetryAxis);
  for (const SymmetryAxis* x : {&a, &b}) {
    // O4 = (3, 0) lies on the line, to where the line's direction is known.
    const Eigen::Vector2d r = Eigen::Vector2d(l.frame, 0.0) - x->point;
    CHECK(std::abs(r.x() * x->direction.y() - r.y() * x->direction.x()) <= t.symmetryAxis * r.norm() + 1e-9);
    CHECK(x->deviation <= t.symmetry * f.fine.size);
  }
}

TEST_CASE("Hoeken's straight run and a circle's run are found at both sample counts, ends to a sample step",
          "[atlas][straight]") {
  SECTION("Hoeken's straight run") {
    const Both f = classified({2.0, 1.0, 2.5, 2.5}, {5.0, 0.0});
    REQUIRE(verdict(f.coarse) == verdict(f.fine));
    REQUIRE(f.coarse.straight.has_value());
    const StraightRun &a = *f.coarse.straight, &b = *f.fine.straight;
    const double step = classifierTolerances(360).runEnd;  // the coarser curve's step
    CAPTURE(a.fromAngle - b.fromAngle, a.toAngle - b.toAngle, a.length - b.length);
    CHECK(angleGap(a.fromAngle, b.fromAngle) <= step);
    CHECK(angleGap(a.toAngle, b.toAngle) <= step);
    // A sample step moves an end by at most the step times P's greatest speed there.
    CHECK(std::abs(a.length - b.length) <= 2.0 * step * 2.0 * f.fine.size);
  }
  SECTION("P at B: a circle of radius 1 about O2, the whole turn") {
    const Both f = classified({3.0, 1.0, 3.0, 2.5}, {0.0, 0.0});
    REQUIRE(verdict(f.coarse) == verdict(f.fine));
    for (const CurveFeatures* g : {&f.coarse, &f.fine}) {
      REQUIRE(g->circular.has_value());
      CHECK(g->circular->radius == Approx(1.0).margin(kCircularTolerance * g->size));
      CHECK(g->circular->centre.norm() <= kCircularTolerance * g->size);
    }
  }
}
