// Tests kinematics/analysis/coupler_curve_features.h on the solver's coupler curves:
// - a cusp constructed where the coupler's instant centre is (the crank line and the rocker
//   line meet there; a point on the moving centrode stops) is found at that crank angle and
//   point, and a curve through no instant centre has none;
// - a figure-eight's crossing is a point the solver's P passes at both crank angles reported,
//   and a circle (P at B) has no crossing, no cusp, and is a circular arc of radius 1 about O2;
// - Norton's symmetric case (coupler = rocker, P on the circle of the coupler's length about
//   C; MechDesigner's "AB = B0B = BK") is symmetric about a line through the rocker pivot, a
//   generic point is not;
// - Hoeken's straight-line linkage (crank 1, coupler 2.5, rocker 2.5, frame 2, P 5 from B on
//   B→C) has a straight run parallel to the frame.

#include "kinematics/analysis/coupler_curve_features.h"

#include "kinematics/analysis/curve_shape_fits.h"
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

double distanceToLine(const Eigen::Vector2d& x, const SymmetryAxis& axis) {
  const Eigen::Vector2d r = x - axis.point;
  return std::abs(r.x() * axis.direction.y() - r.y() * axis.direction.x());
}

}  // namespace

TEST_CASE("a coupler point at the coupler's instant centre gives a cusp at that crank angle and point",
          "[atlas][cusp]") {
  const FourBarLengths l{3.0, 1.0, 3.0, 2.5};  // a crank-rocker
  const double angle = GENERATE(0.3, 1.0, 2.5, 4.0, 5.5);
  CAPTURE(angle);
  const auto bare = makeFourBar(l, Branch::Open);
  REQUIRE(bare.ok());
  const auto pose = solvePose(*bare, {angle, 1.0, 0.0});
  REQUIRE(pose.ok());
  const Eigen::Vector2d o2 = pose->position[fourbar::kO2.index], o4 = pose->position[fourbar::kO4.index];
  const Eigen::Vector2d b = pose->position[fourbar::kB.index], c = pose->position[fourbar::kC.index];
  // I13, the coupler's centre against the frame: where the crank line O2B meets the rocker
  // line O4C.
  const auto centres = fourBarInstantCentres(o2, o4, b, c);
  REQUIRE(centres.ok());
  const InstantCentre& i13 = centres->centre(1, 3);
  REQUIRE(i13.kind == CentreKind::Finite);
  const Eigen::Vector2d u = (c - b).normalized(), n(-u.y(), u.x());
  const CouplerPointSpec p{(i13.position - b).dot(u), (i13.position - b).dot(n)};
  const CouplerCurve curve = test::couplerCurveOf(l, p);
  const CurveFeatures f = classifyCouplerCurve(curve);
  REQUIRE(f.cusps.size() >= 1);
  const Cusp* found = nullptr;
  for (const Cusp& cusp : f.cusps)
    if (std::abs(std::remainder(cusp.crankAngle - angle, 2.0 * kPi)) < 1e-3) found = &cusp;
  REQUIRE(found != nullptr);
  // The Hermite pieces are good to about (1°)⁴ of the curve: the angle to 1e-6 rad, the point to
  // 1e-6 of the size.
  CHECK(std::abs(std::remainder(found->crankAngle - angle, 2.0 * kPi)) < 1e-6);
  CHECK((found->point - i13.position).norm() < 1e-6 * f.size);
  CHECK(found->speed < 1e-6 * f.size);
}

TEST_CASE("a coupler point off the centrode has no cusp", "[atlas][cusp]") {
  const CurveFeatures f = classifyCouplerCurve(test::couplerCurveOf({3.0, 1.0, 3.0, 2.5}, {1.5, 0.2}));
  CHECK(f.cusps.empty());
}

TEST_CASE("a figure-eight's crossing is where the solver's P passes twice, and a circle has none", "[atlas][crunode]") {
  SECTION("figure-eight") {
    // Atlas cell coupler 1.5, rocker 2.5, frame 2.5, P (1.5, 1) coupler lengths: a figure-eight.
    const FourBarLengths l{2.5, 1.0, 1.5, 2.5};
    const CouplerPointSpec p{2.25, 1.5};
    const CurveFeatures f = classifyCouplerCurve(test::couplerCurveOf(l, p));
    REQUIRE(f.crunodes.size() == 1);
    const Crunode& x = f.crunodes.front();
    CAPTURE(x.point.x(), x.point.y(), x.crankAngles[0], x.crankAngles[1]);
    CHECK(std::abs(std::remainder(x.crankAngles[0] - x.crankAngles[1], 2.0 * kPi)) > 0.1);
    for (const double angle : x.crankAngles)
      CHECK((test::couplerPointAt(l, p, angle) - x.point).norm() < 1e-7 * f.size);
  }
  SECTION("circle") {
    const FourBarLengths l{3.0, 1.0, 3.0, 2.5};
    const CurveFeatures f = classifyCouplerCurve(test::couplerCurveOf(l, {0.0, 0.0}));
    CHECK(f.crunodes.empty());
    CHECK(f.cusps.empty());
    REQUIRE(f.circular.has_value());
    CHECK(f.circular->radius == Approx(1.0).margin(1e-9));
    CHECK(f.circular->centre.norm() < 1e-9);
    CHECK(f.circular->turn > 2.0 * kPi * 0.99);
    CHECK(f.symmetry.has_value());
    CHECK(!f.straight.has_value());
  }
}

TEST_CASE("Norton's symmetric coupler curves are symmetric about a line through the rocker pivot",
          "[atlas][symmetric]") {
  // Coupler = rocker = 2.5 and |CP| = 2.5: P = C + 2.5 (cos γ, sin γ) in the coupler's frame.
  const FourBarLengths l{3.0, 1.0, 2.5, 2.5};
  const double gamma = GENERATE(0.6, 1.6, 2.4);
  CAPTURE(gamma);
  const CouplerPointSpec p{2.5 + 2.5 * std::cos(gamma), 2.5 * std::sin(gamma)};
  const CouplerCurve curve = test::couplerCurveOf(l, p);
  const CurveFeatures f = classifyCouplerCurve(curve);
  REQUIRE(f.symmetry.has_value());
  CHECK(f.symmetry->deviation < kSymmetryTolerance * f.size);
  CHECK(distanceToLine(Eigen::Vector2d(l.frame, 0.0), *f.symmetry) < 1e-3 * f.size);

  SECTION("a generic point is not symmetric") {
    const CurveFeatures g = classifyCouplerCurve(test::couplerCurveOf({3.0, 1.0, 2.0, 2.5}, {1.2, 0.7}));
    CHECK(!g.symmetry.has_value());
    // Its best mirror line misses by far more than the tolerance.
    const SymmetryAxis axis{Eigen::Vector2d(l.frame, 0.0), Eigen::Vector2d::UnitX(), 0.0};
    CHECK(mirrorMismatch(test::couplerCurveOf({3.0, 1.0, 2.0, 2.5}, {1.2, 0.7}), axis.point, axis.direction) >
          0.01 * g.size);
  }
}

TEST_CASE("Hoeken's linkage traces a straight run parallel to its frame", "[atlas][straight]") {
  const FourBarLengths l{2.0, 1.0, 2.5, 2.5};
  const CouplerPointSpec p{5.0, 0.0};
  const CouplerCurve curve = test::couplerCurveOf(l, p);
  const CurveFeatures f = classifyCouplerCurve(curve);
  REQUIRE(f.straight.has_value());
  const StraightRun& run = *f.straight;
  CHECK(curve.point[run.firstSample] == run.from);
  CHECK(curve.point[run.lastSample] == run.to);
  CHECK(curve.crankAngle[run.firstSample] == run.fromAngle);
  CAPTURE(run.from.x(), run.from.y(), run.to.x(), run.to.y(), run.fromAngle, run.toAngle, run.deviation);
  CHECK(run.deviation <= kStraightTolerance * f.size);
  CHECK(std::abs(run.to.y() - run.from.y()) < 2.0 * kStraightTolerance * f.size);
  // Over 180° of crank or more (Norton: Hoeken's straight stretch is half a turn).
  CHECK(run.length > 3.0);
  CHECK(std::fmod(run.toAngle - run.fromAngle + 4.0 * kPi, 2.0 * kPi) >= kPi);
  CHECK(f.symmetry.has_value());  // coupler = rocker and |CP| = 2.5: also Norton's case

  SECTION("a generic curve has no straight run") {
    CHECK(!classifyCouplerCurve(test::couplerCurveOf({3.0, 1.0, 3.0, 2.5}, {0.6, 0.4})).straight.has_value());
  }
}
