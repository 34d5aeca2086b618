// The driving torque by virtual work (virtual_work.h) against the Newton–Euler solve
// (inverse_dynamics.h): two methods that share nothing but the pose, equal to round-off at
// every sample of every crank-driven case with masses, loads and gravity, in motion and at rest.

#include "kinematics/dynamics/virtual_work.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/model/driver.h"
#include "kinematics/solve/sweep.h"

#include "tests/kinematics/dynamics/dynamics_cases.h"

#include "tests/support/catch.h"

#include <cmath>

using namespace linkwright::kinematics;

namespace {

// The largest difference between the two torques over `spec`, and the largest torque.
std::pair<double, double> worstDifference(const Mechanism& m, const LinkageDynamics& d, const SweepSpec& spec) {
  const auto s = sweep(m, spec).value();
  const auto f = sweepForces(m, d, s).value();
  const auto& t = f.virtualWorkTorque;
  REQUIRE(t.size() == s.size());
  double worst = 0.0, peak = 0.0;
  std::size_t ok = 0;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!f.ok(j)) continue;
    ++ok;
    worst = std::max(worst, std::abs(t[j] - f.driveTorque[j]));
    peak = std::max(peak, std::abs(f.driveTorque[j]));
  }
  REQUIRE(ok > s.size() / 2);
  return {worst, peak};
}

}  // namespace

TEST_CASE("virtual work gives the Newton–Euler driving torque at every sample of every crank-driven case",
          "[dynamics][virtual-work]") {
  std::vector<linkwright::test::DynamicsCase> cases = linkwright::test::dynamicsCases();
  const auto funsho = findExample("funsho-fourbar").value();
  cases.push_back({"funsho-fourbar", funsho.mechanism, funsho.dynamics, {0.0, 2.0 * kPi, 721, funsho.omega, 0.0}});
  int checked = 0;
  for (const auto& c : cases) {
    if (inputKind(c.mechanism) != InputKind::Angle) continue;
    CAPTURE(c.name);
    const auto [worst, peak] = worstDifference(c.mechanism, c.dynamics, c.spec);
    CHECK(peak > 0.0);
    CHECK(worst <= 1e-9 * peak);
    // At rest and starting (ω = 0, α = 2): the power balance says nothing there; virtual work
    // with the velocities per unit crank rate still does.
    SweepSpec rest = c.spec;
    rest.omega = 0.0;
    rest.alpha = 2.0;
    const auto [restWorst, restPeak] = worstDifference(c.mechanism, c.dynamics, rest);
    CHECK(restWorst <= 1e-9 * restPeak);
    ++checked;
  }
  CHECK(checked >= 5);
}

TEST_CASE("virtual work's torque is for a crank", "[dynamics][virtual-work]") {
  const auto boom = linkwright::test::drivenDynamicsCases();
  for (const auto& c : boom) {
    if (inputKind(c.mechanism) == InputKind::Angle) continue;
    const auto t = CrankVirtualWork::create(c.mechanism, c.dynamics);
    REQUIRE_FALSE(t.ok());
    CHECK(t.error().field == "driver");
    CHECK(t.error().message.find("driven by its") != std::string::npos);
  }
}
