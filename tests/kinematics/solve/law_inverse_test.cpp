// law_inverse.h: when a driver following a law is at a position (a crank at an angle in any
// turn), exact to round-off.

#include "kinematics/solve/law_inverse.h"

#include "kinematics/model/units.h"

#include "tests/support/catch.h"

using namespace linkwright;
namespace k = kinematics;

namespace {
constexpr double kTurn = 2.0 * k::kPi;
}  // namespace

TEST_CASE("the instants a law passes an angle, every turn, in time order", "[law]") {
  // 1 turn/s from 0 for 3 s: a quarter turn at 0.25, 1.25 and 2.25 s.
  const k::TimeBase constant{k::ConstantVelocity{0.0, 2.0 * k::kPi}, 0.0, 3.0};
  const std::vector<double> times = k::timesAtPosition(constant, k::kPi / 2.0, 10, kTurn);
  REQUIRE(times.size() == 3);
  CHECK(times[0] == Approx(0.25).margin(1e-14));
  CHECK(times[1] == Approx(1.25).margin(1e-14));
  CHECK(times[2] == Approx(2.25).margin(1e-14));
  CHECK(k::timesAtPosition(constant, k::kPi / 2.0, 2, kTurn).size() == 2);  // at most `most`
  // A negative angle is the same angle a turn later.
  const std::vector<double> again = k::timesAtPosition(constant, -3.0 * k::kPi / 2.0, 10, kTurn);
  REQUIRE(again.size() == 3);
  for (std::size_t i = 0; i < 3; ++i) CHECK(again[i] == Approx(times[i]).margin(1e-14));
  CHECK(k::lawTravel(constant) == Approx(6.0 * k::kPi).margin(1e-12));
}

TEST_CASE("a cycloidal rise is half way at half its time, and never reaches past its rise", "[law]") {
  const k::TimeBase rise{k::CycloidalRise{0.0, k::kPi, 2.0}, 0.0, 2.0};
  const std::vector<double> half = k::timesAtPosition(rise, k::kPi / 2.0, 10, kTurn);
  REQUIRE(half.size() == 1);
  CHECK(half[0] == Approx(1.0).margin(1e-12));
  CHECK(k::timesAtPosition(rise, 1.5 * k::kPi, 10, kTurn).empty());
  // Nearest: an angle the law never reaches goes to where it comes closest (its end).
  CHECK(k::timeNearestPosition(rise, 1.1 * k::kPi, 0.0, kTurn) == 2.0);
}

TEST_CASE("of several instants at an angle, the one nearest the current instant is chosen", "[law]") {
  const k::TimeBase constant{k::ConstantVelocity{0.0, 2.0 * k::kPi}, 0.0, 3.0};
  CHECK(k::timeNearestPosition(constant, k::kPi, 2.2, kTurn) == Approx(2.5).margin(1e-14));
  CHECK(k::timeNearestPosition(constant, k::kPi, 0.0, kTurn) == Approx(0.5).margin(1e-14));
}

TEST_CASE("a linear driver's position is found as it is, not modulo a turn", "[law]") {
  const k::TimeBase boom{k::CycloidalRise{1.2, 0.7, 4.0}, 0.0, 4.0};
  const std::vector<double> mid = k::timesAtPosition(boom, 1.55, 5);
  REQUIRE(mid.size() == 1);
  CHECK(mid[0] == Approx(2.0).margin(1e-12));
  CHECK(k::timesAtPosition(boom, 1.55 + kTurn, 5).empty());
  CHECK(k::timesAtPosition(boom, 1.2, 5) == std::vector<double>{0.0});
  CHECK(k::timeNearestPosition(boom, 2.5, 0.0) == 4.0);  // never reached: where it comes nearest
  CHECK(k::lawTravel(boom) == Approx(0.7).margin(1e-12));
}
