// Tests kinematics/solve/sweep.h: the sample grid, the spec checks, the column layout for
// each request, agreement with single poses, angle unwrapping, and the report of samples
// that could not be assembled, locked between two samples, or were singular.

#include "kinematics/solve/sweep.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/approx.h"
#include "tests/support/locking_six_bar.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>

using namespace linkwright::kinematics;
using linkwright::test::kThesis;
using linkwright::test::within;

namespace {
constexpr auto kCoupler = fourbar::kCoupler.index;
constexpr auto kRocker = fourbar::kRocker.index;
constexpr auto kC = fourbar::kC.index;

Mechanism fourBar(const FourBarLengths& lengths, Branch branch = Branch::Open) {
  auto m = makeFourBar(lengths, branch);
  REQUIRE(m.ok());
  return *m;
}
}  // namespace

TEST_CASE("sweepAngle spaces samples evenly and hits both ends exactly", "[sweep]") {
  const SweepSpec spec{degToRad(10.0), degToRad(370.0), 13, 1.0, 0.0};
  CHECK(sweepAngle(spec, 0) == spec.fromAngle);
  CHECK(sweepAngle(spec, 12) == spec.toAngle);
  for (std::size_t j = 0; j < 13; ++j)
    CHECK(sweepAngle(spec, j) == within(degToRad(10.0 + 30.0 * static_cast<double>(j)), 1e-14));
  CHECK(sweepAngle({1.5, 9.0, 1, 0.0, 0.0}, 0) == 1.5);
  CHECK(sweepAngle({0.0, -1.0, 3, 0.0, 0.0}, 1) == -0.5);  // a sweep may run backwards
}

TEST_CASE("checkSweepSpec names the bad field", "[sweep][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_FALSE(checkSweepSpec({0.0, 1.0, 10, 2.0, -3.0}).has_value());
  const auto check = [](const SweepSpec& spec, const std::string& field, const std::string& message) {
    const auto e = checkSweepSpec(spec);
    REQUIRE(e.has_value());
    CHECK(e->code == ErrorCode::InvalidValue);
    CHECK(e->field == field);
    CHECK(e->message == message);
  };
  check({nan, 1.0, 10, 1.0, 0.0}, "from angle",
        "from angle must be finite and within ±17453.3 rad (1e6 degrees) (got undefined)");
  check({0.0, inf, 10, 1.0, 0.0}, "to angle",
        "to angle must be finite and within ±17453.3 rad (1e6 degrees) (got undefined)");
  check({0.0, 1.0, 10, -inf, 0.0}, "omega", "omega must be finite and within ±1e6 rad/s (got undefined)");
  check({0.0, 1.0, 10, 1.0, nan}, "alpha", "alpha must be finite and within ±1e12 rad/s² (got undefined)");
  check({0.0, 1.0, 0, 1.0, 0.0}, "samples", "samples must be between 1 and 10000000 (got 0)");

  const auto viaSweep = sweep(fourBar(kThesis), {0.0, 1.0, 0, 1.0, 0.0});
  REQUIRE_FALSE(viaSweep.ok());
  CHECK(viaSweep.error().field == "samples");
  Mechanism broken = fourBar(kThesis);
  broken.links.push_back({"strut", fourbar::kO2, fourbar::kC});
  const auto badMechanism = sweep(broken, {0.0, 1.0, 3, 1.0, 0.0});
  REQUIRE_FALSE(badMechanism.ok());
  CHECK(badMechanism.error().code == ErrorCode::InvalidStructure);
}

TEST_CASE("sweep agrees with solvePose sample by sample", "[sweep]") {
  const Mechanism m = fourBar(kThesis);
  const SweepSpec spec{0.0, 2.0 * kPi, 13, rpmToRadPerSec(10.0), 0.25};
  const auto r = sweep(m, spec);
  REQUIRE(r.ok());
  REQUIRE(r->size() == 13);
  CHECK(r->notAssembled.empty());
  CHECK(r->singularAngles.empty());
  CHECK_FALSE(r->firstFailure.has_value());
  for (std::size_t j = 0; j < r->size(); ++j) {
    CAPTURE(j);
    REQUIRE(r->ok(j));
    const auto p = solvePose(m, {r->inputAngle[j], spec.omega, spec.alpha});
    REQUIRE(p.ok());
    // The sweep runs the same solver on the same branch: identical numbers.
    for (std::size_t i = 0; i < m.points.size(); ++i) {
      CHECK(r->position[i][j] == p->position[i]);
      CHECK(r->velocity[i][j] == p->velocity[i]);
      CHECK(r->acceleration[i][j] == p->acceleration[i]);
    }
    for (std::size_t k = 0; k < m.links.size(); ++k) {
      // Stored angles are unwrapped: equal modulo a turn.
      CHECK(linkwright::test::angleDifference(r->linkAngle[k][j], p->linkAngle[k]) == within(0.0, 1e-12));
      CHECK(r->linkOmega[k][j] == p->linkOmega[k]);
      CHECK(r->linkAlpha[k][j] == p->linkAlpha[k]);
    }
    CHECK(r->transmissionAngle[kC][j] == p->transmissionAngle[kC]);
  }
  // The crank's own angle column runs 0 → 2π without wrapping.
  CHECK(r->linkAngle[fourbar::kCrank.index].back() == within(2.0 * kPi, 1e-12));
}

TEST_CASE("sweep allocates only the requested columns", "[sweep]") {
  const Mechanism m = fourBar(kThesis);
  const SweepSpec spec{0.0, 1.0, 5, 1.0, 0.0};
  const auto positions = sweep(m, spec, {false, false});
  REQUIRE(positions.ok());
  CHECK(positions->velocity.empty());
  CHECK(positions->acceleration.empty());
  CHECK(positions->linkOmega.empty());
  CHECK(positions->linkAlpha.empty());
  CHECK(positions->position.size() == 4);
  CHECK(positions->position[kC].size() == 5);
  CHECK(positions->transmissionAngle[kC].size() == 5);
  CHECK(positions->transmissionAngle[fourbar::kB.index].empty());  // not a dyad

  const auto velocities = sweep(m, spec, {true, false});
  REQUIRE(velocities.ok());
  CHECK(velocities->linkOmega.size() == 3);
  CHECK(velocities->linkAlpha.empty());

  const auto implied = sweep(m, spec, {false, true});
  REQUIRE(implied.ok());
  CHECK(implied->request == SolveRequest{true, true});
  CHECK(implied->linkOmega.size() == 3);
  CHECK(implied->linkAlpha.size() == 3);
}

TEST_CASE("sweep reports the samples it could not assemble", "[sweep][errors]") {
  // Triple-rocker 60/50/35/40: assemblable for |θ| ≤ acos(0.0791667) ≈ 85.46°.
  const Mechanism m = fourBar({60.0, 50.0, 35.0, 40.0});
  const SweepSpec spec{0.0, 2.0 * kPi, 361, 1.0, 0.0};
  const auto r = sweep(m, spec);
  REQUIRE(r.ok());
  REQUIRE(r->notAssembled.size() == 1);
  CHECK(radToDeg(r->notAssembled[0].from) == within(86.0, 1e-9));
  CHECK(radToDeg(r->notAssembled[0].to) == within(274.0, 1e-9));
  REQUIRE(r->firstFailure.has_value());
  // BD = √(50² + 60² − 2·50·60·cos 86°) = 75.3755 mm.
  CHECK(*r->firstFailure ==
        "C cannot be assembled at crank angle 86°: B and O4 are 75.3755 mm apart, "
        "more than coupler + rocker = 75 mm");
  for (std::size_t j = 0; j < r->size(); ++j) {
    CAPTURE(j);
    const bool inside = j <= 85 || j >= 275;
    CHECK(r->assembled(j) == inside);
    // Ground pivots are written once per sweep, not per sample: still 0 where nothing assembles.
    CHECK(r->position[fourbar::kO4.index][j] == (inside ? Eigen::Vector2d(60.0, 0.0) : Eigen::Vector2d::Zero()));
    if (!inside) {
      CHECK(r->report[j].status == PoseStatus::NotAssemblable);
      CHECK(r->report[j].culprit == fourbar::kC);
      CHECK(r->report[j].failure == AssemblyFailure::TooFar);
    }
  }
  CHECK(linkwright::test::firstNonFinite(*r).empty());

  const auto never = sweep(fourBar({100.0, 1.0, 1.0, 1.0}), {0.0, 1.0, 4, 1.0, 0.0});
  REQUIRE(never.ok());
  REQUIRE(never->notAssembled.size() == 1);
  CHECK(never->notAssembled[0] == AngleRange{0.0, 1.0});
  CHECK(never->firstFailure.has_value());
}

TEST_CASE("sweep reports a lock too short to hold a sample", "[sweep][errors]") {
  const auto m = makeSixBar(linkwright::test::lockingSixBar());
  REQUIRE(m.ok());

  const auto coarse = sweep(*m, {0.0, 2.0 * kPi, 73, 1.0, 0.0});
  REQUIRE(coarse.ok());
  CHECK(coarse->notAssembled.empty());
  REQUIRE(coarse->lockedBetween.size() == 1);
  CHECK(radToDeg(coarse->lockedBetween[0].from) == within(290.0, 1e-12));
  CHECK(radToDeg(coarse->lockedBetween[0].to) == within(295.0, 1e-12));
  for (std::size_t j = 0; j + 1 < coarse->size(); ++j) CHECK(coarse->lockedAfter(j) == (j == 58));

  // In 0.05° steps the lock holds a sample, and it is the only one that fails.
  const auto fine = sweep(*m, {0.0, 2.0 * kPi, 7201, 1.0, 0.0});
  REQUIRE(fine.ok());
  CHECK(fine->lockedBetween.empty());
  REQUIRE(fine->notAssembled.size() == 1);
  CHECK(radToDeg(fine->notAssembled[0].from) > 290.0);
  CHECK(radToDeg(fine->notAssembled[0].to) < 295.0);
  CHECK(fine->report[5833].culprit == PointId{6});  // E
}

TEST_CASE("sweep lists the singular samples and keeps their positions", "[sweep]") {
  // Parallelogram 60/25/60/25: toggles at θ = 0 and θ = π (both exact samples here).
  const Mechanism m = fourBar({60.0, 25.0, 60.0, 25.0});
  const auto r = sweep(m, {0.0, 2.0 * kPi, 5, 1.0, 0.0});
  REQUIRE(r.ok());
  CHECK(r->report[0].status == PoseStatus::Singular);
  CHECK(r->report[1].status == PoseStatus::Ok);
  CHECK(r->report[2].status == PoseStatus::Singular);
  CHECK(r->report[3].status == PoseStatus::Ok);
  CHECK(r->report[4].status == PoseStatus::Singular);  // 2π: B.y = 25·sin(2π) ≈ −6e-15, still a toggle
  REQUIRE(r->singularAngles.size() == 3);
  CHECK(r->singularAngles[0] == 0.0);
  CHECK(r->singularAngles[1] == kPi);
  CHECK(r->singularAngles[2] == 2.0 * kPi);
  CHECK(r->notAssembled.empty());
  CHECK_FALSE(r->firstFailure.has_value());
  CHECK(r->position[kC][2].x() == within(35.0, 1e-12));  // C on segment B–O4, 60 from B
  // Rates are not reported at a toggle: their cells stay at the allocation's zero.
  CHECK(r->linkOmega[kRocker][2] == 0.0);
  CHECK(r->linkAlpha[kCoupler][0] == 0.0);
}

TEST_CASE("sweep unwraps link angles across ±180°", "[sweep]") {
  // Double-crank (frame shortest): the rocker turns a full revolution with the crank.
  const Mechanism m = fourBar({25.0, 60.0, 45.0, 70.0});
  const auto r = sweep(m, {0.0, 2.0 * kPi, 73, 1.0, 0.0}, {false, false});
  REQUIRE(r.ok());
  const auto& rocker = r->linkAngle[kRocker];
  CHECK(rocker.back() - rocker.front() == within(2.0 * kPi, 1e-9));
  for (std::size_t j = 1; j < rocker.size(); ++j) CHECK(std::abs(rocker[j] - rocker[j - 1]) < kPi / 2.0);
  // Going backwards unwraps the other way.
  const auto back = sweep(m, {0.0, -2.0 * kPi, 73, 1.0, 0.0}, {false, false});
  REQUIRE(back.ok());
  CHECK(back->linkAngle[kRocker].back() - back->linkAngle[kRocker].front() == within(-2.0 * kPi, 1e-9));
}
