// Stability at the edges: change-point linkages swept through their singular positions, a
// crank a millionth of the frame, lengths at 1e-3 and 1e3 units, and a crank at 1e4 rad/s.
// Every returned column must be finite, or the problem reported as a status or an Error.

#include "kinematics/analysis/grashof.h"
#include "kinematics/analysis/limit_positions.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>

using namespace linkwright::kinematics;
using linkwright::test::angleDifference;
using linkwright::test::checkRate;
using linkwright::test::firstNonFinite;
using linkwright::test::kThesis;
using linkwright::test::near;
using linkwright::test::TimeStencil;
using linkwright::test::within;

namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr auto kB = fourbar::kB.index;
constexpr auto kC = fourbar::kC.index;
constexpr auto kCoupler = fourbar::kCoupler.index;
constexpr auto kRocker = fourbar::kRocker.index;

Mechanism fourBar(const FourBarLengths& lengths, Branch branch = Branch::Open) {
  const auto m = makeFourBar(lengths, branch);
  REQUIRE(m.ok());
  return *m;
}

// One turn in 1° steps: samples 0, 180 and 360 sit exactly on θ = 0, π (kPi, the nearest
// double) and 2π, the change points' singular positions.
constexpr SweepSpec kDegreeTurn{0.0, 2.0 * kPi, 361, 1.0, 0.5};

void checkSingularAtHalfTurns(const SweepResult& s) {
  CHECK(firstNonFinite(s).empty());
  CHECK(s.notAssembled.empty());
  CHECK(s.singularAngles == std::vector<double>{0.0, kPi, 2.0 * kPi});
  for (std::size_t j = 0; j < s.size(); ++j) {
    CAPTURE(j);
    CHECK(s.report[j].status == (j % 180 == 0 ? PoseStatus::Singular : PoseStatus::Ok));
  }
}

}  // namespace

TEST_CASE("A parallelogram stays a parallelogram through its change points", "[extremes]") {
  const FourBarLengths l{60.0, 25.0, 60.0, 25.0};
  REQUIRE(classifyGrashof(l).category == GrashofClass::ChangePoint);
  const auto s = sweep(fourBar(l), kDegreeTurn);
  REQUIRE(s.ok());
  checkSingularAtHalfTurns(*s);
  for (std::size_t j = 0; j < s->size(); ++j) {
    CAPTURE(j);
    std::string why;
    // The coupler translates: C − B = (60, 0). Positions of size ~100: 1e-12.
    CHECK(near(s->position[kC][j] - s->position[kB][j], {60.0, 0.0}, 1e-12, &why));
    INFO(why);
    if (!s->ok(j)) continue;
    // ω3 = 0, ω4 = ω2, α3 = 0, α4 = α2. One degree from a toggle sin μ ≈ 0.017, and the rates'
    // round-off grows like ε/sin²μ ≈ 7e-13 (rrr_dyad.h) of the 2×2 system's terms, which
    // reach ~100 here (|v|² ~ 25², lengths ~60): 1e-8.
    CHECK(s->linkOmega[kCoupler][j] == within(0.0, 1e-8));
    CHECK(s->linkOmega[kRocker][j] == within(1.0, 1e-8));
    CHECK(s->linkAlpha[kCoupler][j] == within(0.0, 1e-8));
    CHECK(s->linkAlpha[kRocker][j] == within(0.5, 1e-8));
  }
  // The rocker turns with the crank: +2π unwrapped.
  CHECK(s->linkAngle[kRocker].back() - s->linkAngle[kRocker].front() == within(2.0 * kPi, 1e-9));
}

TEST_CASE("An antiparallelogram stays crossed through its change points", "[extremes]") {
  const auto s = sweep(fourBar({60.0, 25.0, 60.0, 25.0}, Branch::Crossed), kDegreeTurn);
  REQUIRE(s.ok());
  checkSingularAtHalfTurns(*s);
  for (std::size_t j = 0; j < s->size(); ++j) {
    CAPTURE(j);
    const Eigen::Vector2d b = s->position[kB][j], c = s->position[kC][j];
    const Eigen::Vector2d bToO4 = Eigen::Vector2d(60.0, 0.0) - b;
    // O2, C, O4, B form an isosceles trapezoid whose diagonals are the crossing links BC and
    // O2O4: its bases O2C and BO4 are parallel. A parallelogram's are not (except when flat).
    const double cross = c.x() * bToO4.y() - c.y() * bToO4.x();
    CHECK(cross == within(0.0, 1e-12 * c.norm() * bToO4.norm()));
    if (j % 180 != 0) CHECK((c - b - Eigen::Vector2d(60.0, 0.0)).norm() > 1e-3);
  }
}

TEST_CASE("A kite keeps its folding mode through its change points", "[extremes]") {
  // Frame = rocker = 60, crank = coupler = 25: C is the mirror image of O2 in the line O4–B.
  // At θ = 0 and π that mirror image is O2 itself, where the degenerate mode C ≡ O2 (rocker
  // fixed along the frame) branches off; the tracker must not take it.
  const FourBarLengths l{60.0, 25.0, 25.0, 60.0};
  REQUIRE(classifyGrashof(l).category == GrashofClass::ChangePoint);
  const auto s = sweep(fourBar(l), kDegreeTurn);
  REQUIRE(s.ok());
  checkSingularAtHalfTurns(*s);
  for (std::size_t j = 0; j < s->size(); ++j) {
    CAPTURE(j);
    const Eigen::Vector2d o4(60.0, 0.0);
    const Eigen::Vector2d u = (s->position[kB][j] - o4).normalized();
    const Eigen::Vector2d foot = o4 + u * u.dot(-o4);  // foot of O2 on the line O4–B
    std::string why;
    CHECK(near(s->position[kC][j], 2.0 * foot, 1e-12, &why));
    INFO(why);
  }
}

TEST_CASE("Near a change point the rates still match time differences", "[extremes]") {
  const Mechanism m = fourBar({60.0, 25.0, 60.0, 25.0});
  for (const double deg : {2.0, 5.0, 178.0}) {
    CAPTURE(deg);
    const DriverState state{degToRad(deg), 1.0, 0.5};
    const auto p = solvePose(m, state);
    REQUIRE(p.ok());
    // δ = 1e-4 rad keeps the stencil (±2δ) a degree clear of the toggle. Round-off as in
    // properties_test.cpp: ε·size over sin μ.
    const TimeStencil stencil(m, state, 1e-4 / 1.5);
    const double noise = 64.0 * kEpsilon * 170.0 / std::sin(p->transmissionAngle[kC]);
    for (const LinkId k : {fourbar::kCoupler, fourbar::kRocker}) {
      const auto d = stencil.link(k, noise / 25.0);
      checkRate(p->linkOmega[k.index], d[0], "omega");
      checkRate(p->linkAlpha[k.index], d[1], "alpha");
    }
    for (int axis = 0; axis < 2; ++axis) {
      const auto d = stencil.point(fourbar::kC, axis, noise);
      checkRate(p->velocity[kC][axis], d[0], "velocity of C");
      checkRate(p->acceleration[kC][axis], d[1], "acceleration of C");
    }
  }
}

TEST_CASE("Next to a toggle a pose has meaningful rates or is flagged singular", "[extremes]") {
  // Parallelogram 60/25/60/25 at crank angle θ → 0, ω2 = 1, α2 = 0: exactly ω3 = 0, ω4 = 1,
  // α3 = α4 = 0 at every θ > 0, while sin μ = sin θ → 0. The position there is only as good
  // as B's rounded coordinates, and the rates amplify that: ω's error grows like ε/sin²μ, α's
  // like ε/sin³μ. A pose reported Ok must still carry rates good to three digits of the rate
  // scale ω2² = 1 (far fewer than the CSV prints); below that the solver must say Singular.
  const Mechanism m = fourBar({60.0, 25.0, 60.0, 25.0});
  for (const double angle : {1e-2, 1e-3, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6, 3e-7, 1e-7, 1e-8}) {
    CAPTURE(angle);
    const auto p = solvePose(m, {angle, 1.0, 0.0});
    if (!p.ok()) {
      CHECK(p.error().code == ErrorCode::Singular);
      continue;
    }
    CHECK(p->linkOmega[kCoupler] == within(0.0, 1e-3));
    CHECK(p->linkOmega[kRocker] == within(1.0, 1e-3));
    CHECK(p->linkAlpha[kCoupler] == within(0.0, 1e-3));
    CHECK(p->linkAlpha[kRocker] == within(0.0, 1e-3));
  }
  // Well inside the threshold the pose is singular.
  const auto toggle = solvePose(m, {1e-8, 1.0, 0.0});
  REQUIRE_FALSE(toggle.ok());
  CHECK(toggle.error().code == ErrorCode::Singular);
}

TEST_CASE("A crank a millionth of the frame", "[extremes]") {
  const FourBarLengths l{1.0, 1e-6, 1.0, 1.0};
  const GrashofReport g = classifyGrashof(l);
  REQUIRE(g.category == GrashofClass::CrankRocker);  // S + L = 1 + 1e-6 < P + Q = 2
  CHECK(g.shortest == LinkRole::Crank);
  const Mechanism m = fourBar(l);
  const auto s = sweep(m, {0.0, 2.0 * kPi, 361, 1.0, 0.0});
  REQUIRE(s.ok());
  CHECK(firstNonFinite(*s).empty());
  CHECK(s->singularAngles.empty());
  CHECK(s->notAssembled.empty());
  for (std::size_t j = 0; j < s->size(); ++j) {
    CAPTURE(j);
    // The crank keeps its length to its own ulps, not the frame's.
    CHECK(s->position[kB][j].norm() == within(1e-6, 1e-20));
    // The rocker barely moves: |ω4| ≤ a·ω2/(c·sin μ) with μ ≈ 60°.
    CHECK(std::abs(s->linkOmega[kRocker][j]) < 1.2e-6 * 1.01);
  }
  for (const double deg : {0.0, 100.0, 250.0}) {
    CAPTURE(deg);
    const DriverState state{degToRad(deg), 3.0, -2.0};
    const auto p = solvePose(m, state);
    REQUIRE(p.ok());
    const TimeStencil stencil(m, state, 1e-3 / (3.0 + std::sqrt(2.0)));
    const double noise = 64.0 * kEpsilon * 3.0;  // C: round-off of unit-size coordinates
    for (const LinkId k : {fourbar::kCoupler, fourbar::kRocker}) {
      const auto d = stencil.link(k, noise);
      checkRate(p->linkOmega[k.index], d[0], "omega");
      checkRate(p->linkAlpha[k.index], d[1], "alpha");
    }
  }
  // Time ratio by the classic construction: O2C = 1 ± a in an isosceles triangle of sides 1,
  // so ψ = acos((1 ± a)/2) and β = ψ_folded − ψ_extended ≈ 2a/√3.
  const LimitReport r = fourBarLimitPositions(l, Branch::Open);
  REQUIRE(r.timeRatio.has_value());
  const double beta = std::acos((1.0 - 1e-6) / 2.0) - std::acos((1.0 + 1e-6) / 2.0);
  CHECK(beta == within(2e-6 / std::sqrt(3.0), 1e-15));
  // Q − 1 ≈ 7.4e-7: 1e-12 on Q keeps it to six digits; both sides carry ~1e-16 per angle.
  CHECK(*r.timeRatio == within((kPi + beta) / (kPi - beta), 1e-12));
}

TEST_CASE("Scale invariance from 1e-3 to 1e3 units", "[extremes]") {
  const Mechanism unit = fourBar(kThesis);
  for (const double scale : {1e-3, 1e3}) {
    for (const Branch branch : {Branch::Open, Branch::Crossed}) {
      CAPTURE(scale, branch == Branch::Open);
      const FourBarLengths scaled{kThesis.frame * scale, kThesis.crank * scale, kThesis.coupler * scale,
                                  kThesis.rocker * scale};
      const SweepSpec spec{0.0, 2.0 * kPi, 37, 2.0, 3.0};
      const auto a = sweep(fourBar(kThesis, branch), spec);
      const auto b = sweep(fourBar(scaled, branch), spec);
      REQUIRE((a.ok() && b.ok()));
      CHECK(firstNonFinite(*b).empty());
      for (std::size_t j = 0; j < a->size(); ++j) {
        CAPTURE(j);
        // Scaling by 10^±3 rounds each length by half an ulp; results move by a few ulps.
        for (std::size_t k = 0; k < 3; ++k) {
          CHECK(b->linkAngle[k][j] == within(a->linkAngle[k][j], 1e-12));
          CHECK(b->linkOmega[k][j] == within(a->linkOmega[k][j], 1e-12));
          CHECK(b->linkAlpha[k][j] == within(a->linkAlpha[k][j], 1e-11));
        }
        for (const std::size_t i : {kB, kC}) {
          std::string why;
          CHECK(near(b->position[i][j], scale * a->position[i][j], 1e-12 * scale * 200.0, &why));
          CHECK(near(b->velocity[i][j], scale * a->velocity[i][j], 1e-12 * scale * 1e3, &why));
          CHECK(near(b->acceleration[i][j], scale * a->acceleration[i][j], 1e-12 * scale * 1e4, &why));
          INFO(why);
        }
      }
    }
  }
}

TEST_CASE("A crank at 1e4 rad/s: ω scales linearly, α quadratically", "[extremes]") {
  const Mechanism m = fourBar(kThesis);
  const double fast = 1e4;
  const double alpha2 = 5e3;
  const auto slow = sweep(m, {0.0, 2.0 * kPi, 25, 1.0, 0.0});
  const auto steady = sweep(m, {0.0, 2.0 * kPi, 25, fast, 0.0});
  const auto speeding = sweep(m, {0.0, 2.0 * kPi, 25, fast, alpha2});
  REQUIRE((slow.ok() && steady.ok() && speeding.ok()));
  CHECK(firstNonFinite(*steady).empty());
  CHECK(firstNonFinite(*speeding).empty());
  for (std::size_t j = 0; j < slow->size(); ++j) {
    CAPTURE(j);
    for (std::size_t k = 0; k < 3; ++k) {
      const double w = slow->linkOmega[k][j], a = slow->linkAlpha[k][j];
      // ω = K(θ)·ω2 and α = K(θ)·α2 + K'(θ)·ω2², exactly; round-off 1e-12 of the magnitude.
      CHECK(steady->linkOmega[k][j] == within(fast * w, 1e-12 * fast));
      CHECK(steady->linkAlpha[k][j] == within(fast * fast * a, 1e-12 * fast * fast * 3.0));
      CHECK(speeding->linkAlpha[k][j] == within(fast * fast * a + alpha2 * w, 1e-12 * fast * fast * 3.0));
    }
    std::string why;
    CHECK(near(steady->velocity[kC][j], fast * slow->velocity[kC][j], 1e-12 * fast * 100.0, &why));
    CHECK(
        near(steady->acceleration[kC][j], fast * fast * slow->acceleration[kC][j], 1e-12 * fast * fast * 300.0, &why));
    INFO(why);
  }
}
