// Tests kinematics/solve/rrr_dyad.h: both assembly candidates, the branch sign convention,
// the assembly limits with their relative tolerance, Heron's accuracy near a toggle, and the
// 2×2 rate system with its singularity test.

#include "kinematics/solve/rrr_dyad.h"
#include "kinematics/model/vec2.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <random>

using namespace linkwright::kinematics;
using linkwright::test::near;
using linkwright::test::within;

namespace {}  // namespace

TEST_CASE("rrrCandidates solves a 3-4-5 triangle on both branches", "[rrr_dyad]") {
  const RrrCandidates c = rrrCandidates({0.0, 0.0}, 3.0, {5.0, 0.0}, 4.0);
  REQUIRE(c.failure == AssemblyFailure::None);
  std::string why;
  // Exact in binary up to the last bits of 1.8 and 2.4: a few ulps.
  CHECK(near(c.open, {1.8, 2.4}, 1e-15, &why));
  INFO(why);
  CHECK(near(c.crossed, {1.8, -2.4}, 1e-15, &why));
  CHECK(c.halfSeparation == within(2.4, 1e-15));
  CHECK(c.distance == 5.0);
  // Open: C left of P1→P2, (C−P1)×(C−P2) = +h·L.
  CHECK(cross(c.open - Eigen::Vector2d(0.0, 0.0), c.open - Eigen::Vector2d(5.0, 0.0)) == within(12.0, 1e-13));
  CHECK(cross(c.crossed, c.crossed - Eigen::Vector2d(5.0, 0.0)) == within(-12.0, 1e-13));
}

TEST_CASE("rrrCandidates keeps both lengths for arbitrary placements", "[rrr_dyad]") {
  std::mt19937 rng(20240611);
  // From mt19937's standard-fixed output, not a (library-specific) std distribution.
  const auto fraction = [](std::mt19937& g) { return (static_cast<double>(g()) + 0.5) / 4294967296.0; };
  const auto coordinate = [&](std::mt19937& g) { return -100.0 + 200.0 * fraction(g); };
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector2d p1(coordinate(rng), coordinate(rng));
    const Eigen::Vector2d p2(coordinate(rng), coordinate(rng));
    const double distance = (p2 - p1).norm();
    // l1 anywhere in (0, 2L), l2 inside the assemblable interval [|l1−L|, l1+L].
    const double l1 = (0.01 + 1.98 * fraction(rng)) * distance;
    const double l2 =
        std::abs(l1 - distance) + (0.01 + 0.98 * fraction(rng)) * (l1 + distance - std::abs(l1 - distance));
    CAPTURE(i, l1, l2, distance);
    const RrrCandidates c = rrrCandidates(p1, l1, p2, l2);
    REQUIRE(c.failure == AssemblyFailure::None);
    // Lengths up to ~400: round-off of a few ulps each, so 1e-12 relative to the lengths.
    const double tolerance = 1e-12 * (l1 + l2 + distance);
    for (const Eigen::Vector2d& point : {c.open, c.crossed}) {
      CHECK((point - p1).norm() == within(l1, tolerance));
      CHECK((point - p2).norm() == within(l2, tolerance));
    }
    CHECK(cross(c.open - p1, c.open - p2) > 0.0);
    CHECK(cross(c.crossed - p1, c.crossed - p2) < 0.0);
    CHECK((c.open - c.crossed).norm() == within(2.0 * c.halfSeparation, tolerance));
  }
}

TEST_CASE("rrrCandidates reports why a dyad cannot be assembled", "[rrr_dyad][errors]") {
  CHECK(rrrCandidates({0.0, 0.0}, 3.0, {8.0, 0.0}, 4.0).failure == AssemblyFailure::TooFar);
  CHECK(rrrCandidates({0.0, 0.0}, 10.0, {5.0, 0.0}, 4.0).failure == AssemblyFailure::TooClose);
  CHECK(rrrCandidates({0.0, 0.0}, 4.0, {3.0, 0.0}, 10.0).failure == AssemblyFailure::TooClose);
  CHECK(rrrCandidates({2.0, 3.0}, 4.0, {2.0, 3.0}, 4.0).failure == AssemblyFailure::Coincident);
  const RrrCandidates far = rrrCandidates({0.0, 0.0}, 3.0, {8.0, 0.0}, 4.0);
  CHECK(far.distance == 8.0);
}

TEST_CASE("rrrCandidates treats a gap within kAssemblyTolerance as the limit itself", "[rrr_dyad]") {
  const double sum = 7.0;  // l1 + l2
  // Exactly stretched: one position, on the line.
  const RrrCandidates exact = rrrCandidates({0.0, 0.0}, 3.0, {sum, 0.0}, 4.0);
  REQUIRE(exact.failure == AssemblyFailure::None);
  CHECK(exact.halfSeparation == 0.0);
  CHECK(exact.open == Eigen::Vector2d(3.0, 0.0));
  // Past the limit by a tenth of the tolerance: round-off, taken as the limit.
  const RrrCandidates slack = rrrCandidates({0.0, 0.0}, 3.0, {sum * (1.0 + 0.1 * kAssemblyTolerance), 0.0}, 4.0);
  REQUIRE(slack.failure == AssemblyFailure::None);
  CHECK(slack.halfSeparation == 0.0);
  // Past it by ten times the tolerance: a real gap.
  CHECK(rrrCandidates({0.0, 0.0}, 3.0, {sum * (1.0 + 10.0 * kAssemblyTolerance), 0.0}, 4.0).failure ==
        AssemblyFailure::TooFar);
  // The same on the inner limit |l1 − l2| = 1.
  CHECK(rrrCandidates({0.0, 0.0}, 3.0, {1.0 - 0.1 * kAssemblyTolerance * sum, 0.0}, 4.0).failure ==
        AssemblyFailure::None);
  CHECK(rrrCandidates({0.0, 0.0}, 3.0, {1.0 - 10.0 * kAssemblyTolerance * sum, 0.0}, 4.0).failure ==
        AssemblyFailure::TooClose);
}

TEST_CASE("rrrCandidates past a limit within the tolerance keeps both lengths to it", "[rrr_dyad]") {
  // Found by the random-linkage soak (a kite 1e-10 off its change point): past the inner limit
  // the foot of the old formula lay slack·l2/L beyond the first circle, here 1e-5 for a
  // tolerance of 2e-10. Now the first length holds and the second misses by the gap.
  struct Case {
    double l1, l2, distance;
  };
  const double l = 1.0, d = 1e-6, gap = 1e-11;  // gap < kAssemblyTolerance·(l1 + l2) = 2e-10
  for (const Case c : {Case{l, l - d, d - gap}, Case{l - d, l, d - gap}, Case{l, 2.0 * l, 3.0 * l + gap},
                       Case{2.0 * l, l, 3.0 * l + gap}}) {
    CAPTURE(c.l1, c.l2, c.distance);
    const Eigen::Vector2d p1(0.3, -0.2);
    const Eigen::Vector2d p2 = p1 + c.distance * Eigen::Vector2d(0.6, 0.8);
    const RrrCandidates r = rrrCandidates(p1, c.l1, p2, c.l2);
    REQUIRE(r.failure == AssemblyFailure::None);
    CHECK(r.halfSeparation == 0.0);
    const double tolerance = kAssemblyTolerance * (c.l1 + c.l2);
    CHECK((r.open - p1).norm() == within(c.l1, tolerance));
    CHECK((r.open - p2).norm() == within(c.l2, tolerance));
  }
}

TEST_CASE("rrrCandidates keeps h accurate next to a toggle (Heron's form)", "[rrr_dyad]") {
  // l1 = l2 = 1 and L = 2 − ε: h = √(1 − (L/2)²) = √((1 − L/2)(1 + L/2)), where 1 − L/2 is exact
  // (Sterbenz). The textbook √(l1² − a²) would lose about half the digits here (1e-16/ε).
  for (const double gap : {1e-4, 1e-8, 1e-12}) {
    CAPTURE(gap);
    const double distance = 2.0 - gap;
    const double expected = std::sqrt((1.0 - distance / 2.0) * (1.0 + distance / 2.0));
    const RrrCandidates c = rrrCandidates({0.0, 0.0}, 1.0, {distance, 0.0}, 1.0);
    REQUIRE(c.failure == AssemblyFailure::None);
    // A handful of roundings in Heron's product: 1e-14 relative.
    CHECK(c.halfSeparation == within(expected, 1e-14 * expected));
  }
}

TEST_CASE("rrrSine is |sin| of the angle at C", "[rrr_dyad]") {
  CHECK(rrrSine({0.0, 1.0}, {0.0, 0.0}, {1.0, 1.0}) == within(1.0, 1e-15));
  CHECK(rrrSine({1.0, 1.0}, {0.0, 0.0}, {2.0, 0.0}) == within(1.0, 1e-15));
  CHECK(rrrSine({std::sqrt(3.0), 1.0}, {0.0, 0.0}, {std::sqrt(3.0), 0.0}) == within(std::sqrt(3.0) / 2.0, 1e-15));
  CHECK(rrrSine({3.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}) == 0.0);
  CHECK(rrrSine({0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}) == 0.0);  // C on P1: no angle, reported 0
}

TEST_CASE("rrrSolveRates solves the 2×2 system and refuses a singular one", "[rrr_dyad]") {
  const Eigen::Vector2d r1(3.0, 1.0);
  const Eigen::Vector2d r2(-1.0, 2.0);
  const Eigen::Vector2d x(0.5, -2.0);
  const Eigen::Vector2d rhs(r1.dot(x), r2.dot(x));
  Eigen::Vector2d solved(99.0, 99.0);
  REQUIRE(rrrSolveRates(r1, r2, rhs, solved));
  std::string why;
  CHECK(near(solved, x, 1e-15, &why));
  INFO(why);

  Eigen::Vector2d untouched(7.0, 8.0);
  CHECK_FALSE(rrrSolveRates({2.0, 0.0}, {-3.0, 0.0}, {1.0, 1.0}, untouched));
  CHECK(untouched == Eigen::Vector2d(7.0, 8.0));
  // Just above and below the threshold |r1×r2| = kSingularSine·|r1||r2|.
  CHECK(rrrSolveRates({1.0, 0.0}, {-1.0, 2.0 * kSingularSine}, {0.0, 1.0}, untouched));
  CHECK_FALSE(rrrSolveRates({1.0, 0.0}, {-1.0, 0.5 * kSingularSine}, {0.0, 1.0}, untouched));
}
