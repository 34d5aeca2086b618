// Tests a sweep on a time base (sweep.h's TimeBase): the thesis crank-rocker started from
// rest by a ramp law. At every instant the crank's angle, ω and α are the law's, every link's
// ω and α are those of the exact solver at that state (α₂ ≠ 0 terms included), and they are
// the time derivatives of the swept angles (central differences in time). The CSV gains a
// time_s column; bad time bases are refused.

#include "kinematics/io/csv_writer.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/solve/sweep.h"

#include "tests/support/approx.h"

#include "tests/support/catch.h"

#include <sstream>

using namespace linkwright::kinematics;
using linkwright::test::within;

namespace {

constexpr std::size_t kCrank = fourbar::kCrank.index;
constexpr std::size_t kCoupler = fourbar::kCoupler.index;
constexpr std::size_t kRocker = fourbar::kRocker.index;

Mechanism thesis() { return makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value(); }

// From rest to 10 rpm in 2 s, then on at 10 rpm: 3 s sampled every 10 ms.
SweepSpec rampSpec() {
  SweepSpec spec;
  spec.samples = 301;
  spec.time = TimeBase{RampToSpeed{0.0, rpmToRadPerSec(10.0), 2.0}, 0.0, 3.0};
  return spec;
}

}  // namespace

TEST_CASE("on a time base the crank follows the law and every rate is the exact solver's", "[sweep][time]") {
  const Mechanism m = thesis();
  const SweepSpec spec = rampSpec();
  const auto result = sweep(m, spec);
  REQUIRE(result);
  REQUIRE(result->time.size() == spec.samples);
  const MotionLaw& law = spec.time->law;
  for (std::size_t j = 0; j < spec.samples; ++j) {
    const double t = result->time[j];
    CAPTURE(t);
    CHECK(t == within(0.01 * static_cast<double>(j), 1e-15));
    const DriverState s = motionAt(law, t);
    CHECK(result->inputAngle[j] == s.position);
    CHECK(result->linkOmega[kCrank][j] == s.velocity);
    CHECK(result->linkAlpha[kCrank][j] == s.acceleration);
    // The coupler's and rocker's rates at the law's (θ₂, ω₂, α₂): the solver's own answer.
    const Pose exact = solvePose(m, {s.position, s.velocity, s.acceleration}).value();
    for (const std::size_t k : {kCoupler, kRocker}) {
      CHECK(result->linkOmega[k][j] == exact.linkOmega[k]);
      CHECK(result->linkAlpha[k][j] == exact.linkAlpha[k]);
    }
  }
  // While the crank accelerates, the rocker's α is not what ω₂ alone gives: the α₂ term shows.
  const DriverState s = motionAt(law, 1.0);
  const Pose withoutAlpha = solvePose(m, {s.position, s.velocity, 0.0}).value();
  CHECK(std::abs(result->linkAlpha[kRocker][100] - withoutAlpha.linkAlpha[kRocker]) > 1e-3);
}

TEST_CASE("on a time base ω and α are the time derivatives of the swept angles", "[sweep][time]") {
  // Central differences in time of the rocker's angle and ω, solved at the law's states t ± h;
  // O(h²) with h = 1e-5 s, against rates of order 1 rad/s and 1 rad/s².
  const Mechanism m = thesis();
  const SweepSpec spec = rampSpec();
  const MotionLaw& law = spec.time->law;
  const auto at = [&](double t) {
    const DriverState s = motionAt(law, t);
    return solvePose(m, {s.position, s.velocity, s.acceleration}).value();
  };
  const double h = 1e-5;
  for (const double t : {0.35, 1.0, 1.7, 2.5}) {
    CAPTURE(t);
    const Pose before = at(t - h), now = at(t), after = at(t + h);
    for (const std::size_t k : {kCoupler, kRocker}) {
      const double dAngle = std::remainder(after.linkAngle[k] - before.linkAngle[k], 2.0 * kPi) / (2.0 * h);
      CHECK(dAngle == within(now.linkOmega[k], 1e-7));
      CHECK((after.linkOmega[k] - before.linkOmega[k]) / (2.0 * h) == within(now.linkAlpha[k], 1e-5));
    }
  }
}

TEST_CASE("a time-base CSV starts with time_s", "[sweep][time][csv]") {
  const Mechanism m = thesis();
  SweepSpec spec = rampSpec();
  spec.samples = 4;
  const auto result = sweep(m, spec);
  REQUIRE(result);
  std::ostringstream csv;
  io::writeSweepCsv(csv, m, *result);
  const std::string text = csv.str();
  CHECK(text.rfind("time_s,crank_angle_deg,crank_omega_rad_s,crank_alpha_rad_s2,", 0) == 0);
  CHECK(text.find("\r\n1,") != std::string::npos);  // the row at t = 1 s
  // Without a time base there is no time column.
  const auto angles = sweep(m, SweepSpec{0.0, 1.0, 3, 1.0, 0.0});
  REQUIRE(angles);
  CHECK(angles->time.empty());
}

TEST_CASE("a bad time base is refused with the reason", "[sweep][time][errors]") {
  const Mechanism m = thesis();
  SweepSpec backwards = rampSpec();
  backwards.time->fromTime = 2.0;
  backwards.time->toTime = 1.0;
  CHECK_THAT(sweep(m, backwards).error().message, Catch::Contains("to time must not be before from time"));
  SweepSpec table = rampSpec();
  table.time->law = makeTableLaw({0.0, 0.5, 1.0, 1.5}, {0.0, 0.1, 0.3, 0.6}).value();
  CHECK_THAT(sweep(m, table).error().message, Catch::Contains("leave the law's table, which runs from 0 to 1.5 s"));
  // 1e6 rad/s for 1e6 s would turn the crank 1e12 rad: past the domain's ±1e6 degrees.
  SweepSpec endless = rampSpec();
  endless.time = TimeBase{ConstantVelocity{0.0, 1e6}, -1e6, 1e6};
  CHECK_THAT(sweep(m, endless).error().message,
             Catch::Contains("the law's angle at -1e+06 s would be -1e+12, beyond ±17453.3 rad"));
  SweepSpec badLaw = rampSpec();
  badLaw.time->law = CycloidalRise{0.0, 1.0, -1.0};
  CHECK_THAT(sweep(m, badLaw).error().message, Catch::Contains("law.duration"));
}
