// Tests kinematics/solve/motion_law.h: each law's rates against finite differences of its
// positions, the textbook figures (a cycloidal rise's peak acceleration 2πh/T², the 3-4-5
// rise's mid-stroke speed 15h/8T), the table spline reproducing a cubic to round-off, and
// the errors for bad laws.

#include "kinematics/solve/motion_law.h"

#include "kinematics/model/units.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

// Central differences of q and q̇ at t: O(h²) errors, h = 1e-5 of the law's time scale.
void checkRatesAgainstDifferences(const MotionLaw& law, double t, double timeScale) {
  const double h = 1e-5 * timeScale;
  const DriverState s = motionAt(law, t);
  const DriverState before = motionAt(law, t - h), after = motionAt(law, t + h);
  const double velocityScale = std::max(1.0, std::abs(s.velocity));
  const double accelerationScale = std::max(1.0 / timeScale, std::abs(s.acceleration));
  CAPTURE(t, s.position, s.velocity, s.acceleration);
  CHECK((after.position - before.position) / (2.0 * h) == within(s.velocity, 1e-7 * velocityScale));
  CHECK((after.velocity - before.velocity) / (2.0 * h) == within(s.acceleration, 1e-6 * accelerationScale));
}

}  // namespace

TEST_CASE("every closed-form law's rates are the time derivatives of its position", "[motion_law]") {
  const std::vector<std::pair<const char*, MotionLaw>> laws{
      {"constant", ConstantVelocity{0.3, 2.5}},
      {"ramp", RampToSpeed{-1.0, rpmToRadPerSec(10.0), 2.0}},
      {"cycloidal", CycloidalRise{0.5, degToRad(90.0), 0.8}},
      {"3-4-5", PolynomialRise{0.0, -2.0, 1.5}},
  };
  for (const auto& [name, law] : laws) {
    CAPTURE(name);
    REQUIRE_FALSE(checkMotionLaw(law).has_value());
    for (const double t : {0.013, 0.2, 0.4, 0.61, 0.79, 1.1, 1.49, 1.9, 2.7}) checkRatesAgainstDifferences(law, t, 1.0);
  }
}

TEST_CASE("a ramp starts at rest, accelerates evenly and cruises at its speed", "[motion_law]") {
  const RampToSpeed ramp{1.0, 3.0, 2.0};
  CHECK(motionAt(ramp, -1.0) == DriverState{1.0, 0.0, 0.0});
  CHECK(motionAt(ramp, 1.0) == DriverState{1.0 + 0.5 * 1.5 * 1.0, 1.5, 1.5});
  // At the end of the ramp q = q0 + vT/2, and it goes on at v.
  CHECK(motionAt(ramp, 2.0).position == 1.0 + 3.0);
  CHECK(motionAt(ramp, 3.0) == DriverState{1.0 + 3.0 + 3.0, 3.0, 0.0});
}

TEST_CASE("a cycloidal rise peaks at 2πh/T² and dwells at both ends", "[motion_law]") {
  const double h = degToRad(60.0), T = 0.5;
  const CycloidalRise law{0.2, h, T};
  // At u = 1/4, sin 2πu is 1: the peak acceleration, exactly.
  CHECK(motionAt(law, T / 4.0).acceleration == within(2.0 * kPi * h / (T * T), 1e-15));
  CHECK(motionAt(law, T / 2.0).velocity == within(2.0 * h / T, 1e-15));
  CHECK(motionAt(law, 0.0) == DriverState{0.2, 0.0, 0.0});
  CHECK(motionAt(law, T) == DriverState{0.2 + h, 0.0, 0.0});
  CHECK(motionAt(law, 2.0 * T) == DriverState{0.2 + h, 0.0, 0.0});
}

TEST_CASE("a 3-4-5 rise is at mid-stroke at T/2, at 15h/8T", "[motion_law]") {
  const double h = 2.0, T = 4.0;
  const PolynomialRise law{1.0, h, T};
  const DriverState mid = motionAt(law, T / 2.0);
  CHECK(mid.position == within(1.0 + h / 2.0, 1e-15));
  CHECK(mid.velocity == within(15.0 * h / (8.0 * T), 1e-15));
  CHECK(mid.acceleration == within(0.0, 1e-15));
  // Peak acceleration 10h/(√3 T²) at u = (3 − √3)/6.
  CHECK(motionAt(law, T * (3.0 - std::sqrt(3.0)) / 6.0).acceleration ==
        within(10.0 * h / (std::sqrt(3.0) * T * T), 1e-14));
}

TEST_CASE("a table law reproduces a cubic to round-off, at and between its rows", "[motion_law]") {
  const auto q = [](double t) { return 0.5 - 1.25 * t + 0.75 * t * t + 0.3 * t * t * t; };
  const auto dq = [](double t) { return -1.25 + 1.5 * t + 0.9 * t * t; };
  const auto ddq = [](double t) { return 1.5 + 1.8 * t; };
  // Uneven rows, as a measured θ(t) has them.
  std::vector<double> time{0.0, 0.1, 0.25, 0.3, 0.55, 0.8, 0.85, 1.2, 1.6, 2.0};
  std::vector<double> position;
  for (const double t : time) position.push_back(q(t));
  const auto law = makeTableLaw(time, position);
  REQUIRE(law);
  REQUIRE_FALSE(checkMotionLaw(*law).has_value());
  for (double t = 0.0; t <= 2.0; t += 0.0371) {
    CAPTURE(t);
    const DriverState s = motionAt(*law, t);
    CHECK(s.position == within(q(t), 1e-14));
    CHECK(s.velocity == within(dq(t), 1e-13));
    CHECK(s.acceleration == within(ddq(t), 1e-12));
  }
  CHECK(lawTimeSpan(*law) == std::pair{0.0, 2.0});
  CHECK_FALSE(lawTimeSpan(CycloidalRise{0.0, 1.0, 1.0}).has_value());
}

TEST_CASE("bad laws are refused with the field and the value", "[motion_law][errors]") {
  const auto message = [](const MotionLaw& law) { return checkMotionLaw(law).value().message; };
  CHECK_THAT(message(CycloidalRise{0.0, 1.0, 0.0}),
             Catch::Contains("law.duration must be positive") && Catch::Contains("(got 0)"));
  CHECK_THAT(message(RampToSpeed{0.0, 1.0, -2.0}), Catch::Contains("law.rampTime"));
  CHECK_THAT(message(ConstantVelocity{0.0, 2e6}), Catch::Contains("law peak velocity") && Catch::Contains("2e+06"));
  // A rise of a radian in a microsecond: 6e12 rad/s², past the domain's α.
  CHECK_THAT(message(CycloidalRise{0.0, 1.0, 1e-6}), Catch::Contains("law peak velocity"));
  CHECK_THAT(message(PolynomialRise{std::nan(""), 1.0, 1.0}), Catch::Contains("law.start must be finite"));
  CHECK_THAT(makeTableLaw({0.0, 1.0, 2.0}, {0.0, 1.0, 2.0}).error().message, Catch::Contains("at least four rows"));
  // Lists of different lengths are not too few rows (it said "needs at least four rows (got 5)").
  CHECK(makeTableLaw({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 1.0, 2.0, 3.0}).error().message ==
        "law.table has 5 times but 4 positions: the two lists must have the same length, one position per time");
  CHECK_THAT(makeTableLaw({0.0, 1.0, 1.0, 2.0}, {0.0, 1.0, 2.0, 3.0}).error().message,
             Catch::Contains("law.table[2].time must be later than the row before (got 1 after 1)"));
  CHECK_THAT(makeTableLaw({0.0, 1.0, 2.0, 3.0}, {0.0, INFINITY, 2.0, 3.0}).error().message,
             Catch::Contains("law.table[1].position"));
}

TEST_CASE("a law's computed peaks are never echoed as nan or inf as if typed", "[law][errors]") {
  // A ramp of 5e-324 s: its peak acceleration v/T overflows.
  const auto ramp = checkMotionLaw(RampToSpeed{0.0, 1.0, 5e-324});
  REQUIRE(ramp);
  CHECK(ramp->field == "law peak acceleration");
  CHECK(ramp->message == "law peak acceleration overflows for these inputs (beyond ±1e12 rad/s²)");
  // Finite but out of range: what it would be.
  const auto steep = checkMotionLaw(RampToSpeed{0.0, 1e6, 1e-7});
  REQUIRE(steep);
  CHECK(steep->message == "law peak acceleration would be 1e+13, beyond ±1e12 rad/s²");
  // Rows 1e-300 s apart: the spline overflows; std::max dropped its NaN and the time base then
  // said "the law's angle at 0 s … (got undefined)".
  const auto table = makeTableLaw({0.0, 1e-300, 2e-300, 3e-300}, {0.0, 0.1, 0.2, 0.3});
  if (table) {
    const auto e = checkMotionLaw(*table);
    REQUIRE(e);
    CHECK_THAT(e->message, !Catch::Contains("nan") && !Catch::Contains("inf") && Catch::Contains("overflows"));
  }
}
