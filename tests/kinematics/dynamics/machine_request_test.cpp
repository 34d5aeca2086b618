// machine as one request (machine_request.h): its fields checked once and spelled for each front
// end, and its figures at the defaults within 1e-9 of an independent dense computation — the
// forces at 0.01° steps integrated by Simpson's rule, E's extremes by a parabola through the
// three best samples, the peaks off a 2·10⁻⁵ rad scan around them — on a four-bar, a slider-crank
// and a Watt II six-bar, with masses, gravity and a gearbox that loses 15 %.

#include "kinematics/dynamics/machine_request.h"
#include "kinematics/design/examples.h"
#include "kinematics/design/sweep_grid.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

using namespace linkwright::kinematics;

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

// An example with its own masses, or every link made a 0.3 kg bar, under gravity.
Example withMasses(const std::string& name) {
  Example e = findExample(name).value();
  if (e.dynamics.empty()) {
    for (const Link& link : e.mechanism.links) e.dynamics.links.push_back({link.name, 0.3, std::nullopt, std::nullopt});
    e.dynamics.loads.gravity = standardGravity();
  }
  return e;
}

// The dense independent reading of a turn: the solver's forces at `n` + 1 samples.
struct Dense {
  double mean = 0.0, rms = 0.0, peak = 0.0, energy = 0.0, shaking = 0.0, motorRms = 0.0, motorMeanPower = 0.0;
};

// The largest of f over a fine scan of ±2 samples' width around the best of `values` (dense
// forces again at 2e-5 rad), so the peak is read off the solver, not an interpolant.
template <typename F>
double scannedPeak(const Example& e, double omega, const std::vector<double>& angle, const std::vector<double>& values,
                   F f) {
  const std::size_t best = static_cast<std::size_t>(std::max_element(values.begin(), values.end()) - values.begin());
  const double width = 2.0 * (angle[1] - angle[0]);
  const std::size_t n = static_cast<std::size_t>(2.0 * width / 2e-5) + 1;
  const auto scan = turnForces(e.mechanism, e.dynamics,
                               SweepSpec{angle[best] - width, angle[best] + width, n, omega, 0.0}, omega, 0.0);
  REQUIRE(scan.ok());
  double peak = 0.0;
  for (std::size_t j = 0; j < n; ++j) peak = std::max(peak, f(scan->forces, j));
  return peak;
}

Dense dense(const Example& e, double omega, double gear, double eta) {
  const std::size_t n = 36000;  // 0.01°; Simpson's error ~h⁴ ≈ 1e-15 of the integrands
  const SweepSpec turn{degToRad(e.fromDeg), degToRad(e.fromDeg) + kTurn, n + 1, omega, 0.0};
  const auto t = turnForces(e.mechanism, e.dynamics, turn, omega, 0.0);
  REQUIRE(t.ok());
  const std::vector<double>& torque = t->forces.driveTorque;
  const double h = kTurn / static_cast<double>(n);
  const auto simpson = [&](auto f) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 2 <= n; i += 2) sum += h / 3.0 * (f(i) + 4.0 * f(i + 1) + f(i + 2));
    return sum / kTurn;
  };
  Dense d;
  d.mean = simpson([&](std::size_t i) { return torque[i]; });
  d.rms = std::sqrt(simpson([&](std::size_t i) { return torque[i] * torque[i]; }));
  // Through the gearbox: T/(Nη) driving, Tη/N driven back (ω > 0 drives where T > 0).
  const auto motor = [&](std::size_t i) { return torque[i] > 0.0 ? torque[i] / (gear * eta) : torque[i] * eta / gear; };
  d.motorRms = std::sqrt(simpson([&](std::size_t i) { return motor(i) * motor(i); }));
  d.motorMeanPower = simpson([&](std::size_t i) { return motor(i) * gear * omega; });
  // E at every even sample by Simpson, at odd ones by the half-interval weights; its extremes
  // by the parabola through the best sample and its neighbours.
  std::vector<double> energy(n + 1, 0.0);
  for (std::size_t i = 0; i + 2 <= n; i += 2) {
    const double a = d.mean - torque[i], b = d.mean - torque[i + 1], c = d.mean - torque[i + 2];
    energy[i + 1] = energy[i] + h / 12.0 * (5.0 * a + 8.0 * b - c);
    energy[i + 2] = energy[i] + h / 3.0 * (a + 4.0 * b + c);
  }
  const auto refined = [&](std::size_t j, double sign) {
    const double l = sign * energy[(j + n - 1) % n], m = sign * energy[j], r = sign * energy[(j + 1) % n];
    return sign * (m + (r - l) * (r - l) / (8.0 * (2.0 * m - l - r)));
  };
  const std::size_t high =
      static_cast<std::size_t>(std::max_element(energy.begin(), energy.end() - 1) - energy.begin());
  const std::size_t low = static_cast<std::size_t>(std::min_element(energy.begin(), energy.end() - 1) - energy.begin());
  d.energy = refined(high, 1.0) - refined(low, -1.0);
  std::vector<double> angle(n + 1), absTorque(n + 1), shake(n + 1);
  for (std::size_t j = 0; j <= n; ++j) {
    angle[j] = turn.fromAngle + h * static_cast<double>(j);
    absTorque[j] = std::abs(torque[j]);
    shake[j] = t->forces.shakingForce[j].norm();
  }
  d.peak = scannedPeak(e, omega, angle, absTorque,
                       [](const ForceSweep& f, std::size_t j) { return std::abs(f.driveTorque[j]); });
  d.shaking =
      scannedPeak(e, omega, angle, shake, [](const ForceSweep& f, std::size_t j) { return f.shakingForce[j].norm(); });
  return d;
}

}  // namespace

TEST_CASE("machine's figures at the defaults are within 1e-9 of a dense independent computation",
          "[dynamics][machine][request]") {
  for (const std::string name : {"funsho-fourbar", "ls3-engine", "watt-ii"}) {
    CAPTURE(name);
    const Example e = withMasses(name);
    const double gear = 5.0, eta = 0.85;
    const MachineRequest request = machineRequest({{"gear_ratio", gear}, {"efficiency", eta}}, FrontEnd::Cli).value();
    const auto run = runMachine(e.mechanism, e.dynamics, machineDefaultsOf(sweepGridOf(e)), request);
    REQUIRE(run.ok());
    CHECK(run->converged);
    CHECK(run->duty.worstAccuracy() <= kMachineTolerance);
    const MachineDuty& d = run->duty;
    const Dense x = dense(e, e.omega, gear, eta);
    CHECK(d.meanTorque == Approx(x.mean).margin(1e-9 * x.peak));
    CHECK(d.rmsTorque == Approx(x.rms).epsilon(1e-9));
    CHECK(d.peakTorque == Approx(x.peak).epsilon(1e-9));
    CHECK(d.energyFluctuation == Approx(x.energy).epsilon(1e-9));
    CHECK(d.shakingForcePeak == Approx(x.shaking).epsilon(1e-9));
    CHECK(d.motor.rmsTorque == Approx(x.motorRms).epsilon(1e-9));
    CHECK(d.motor.meanPower == Approx(x.motorMeanPower).margin(1e-9 * d.motor.peakPower));
    // The figures read straight off the samples, as before, miss by far more than that.
    double sampledPeak = 0.0;
    for (const double t : d.torque) sampledPeak = std::max(sampledPeak, std::abs(t));
    CHECK(std::abs(sampledPeak - x.peak) > 1e-8 * x.peak);
  }
}

TEST_CASE("machine reads the turn on the first grid whose estimates are within the tolerance",
          "[dynamics][machine][request]") {
  const Example e = withMasses("ls3-engine");
  for (const double tolerance : {1e-4, 1e-9, 1e-12}) {
    CAPTURE(tolerance);
    const MachineRequest request = machineRequest({{"tolerance", tolerance}}, FrontEnd::Cli).value();
    const auto run = runMachine(e.mechanism, e.dynamics, machineDefaultsOf(sweepGridOf(e)), request);
    REQUIRE(run.ok());
    CHECK(run->converged);
    CHECK(run->duty.worstAccuracy() <= tolerance);
    CHECK((run->samples - 1) % kMachineFirstIntervals == 0);
    if (run->samples > kMachineFirstIntervals + 1) {
      // The grid before it was not enough.
      const SweepSpec before{degToRad(e.fromDeg), degToRad(e.fromDeg) + kTurn, (run->samples - 1) / 2 + 1, e.omega,
                             0.0};
      CHECK(machineDuty(e.mechanism, e.dynamics, before, request.duty)->worstAccuracy() > tolerance);
    }
  }
  // Samples given are read exactly, with the error they leave said.
  const MachineRequest coarse = machineRequest({{"samples", 13.0}, {"tolerance", 1e-12}}, FrontEnd::Cli).value();
  const auto run = runMachine(e.mechanism, e.dynamics, machineDefaultsOf(sweepGridOf(e)), coarse);
  REQUIRE(run.ok());
  CHECK(run->samples == 13);
  CHECK_FALSE(run->converged);
  CHECK(run->duty.worstAccuracy() > 1e-12);
}

TEST_CASE("a machine run reports progress and stops when cancelled", "[dynamics][machine][request]") {
  const Example e = withMasses("funsho-fourbar");
  const MachineRequest request = machineRequest({}, FrontEnd::Python).value();
  std::vector<std::pair<std::size_t, std::size_t>> seen;
  RunControl control;
  control.progress = [&](std::size_t done, std::size_t total) { seen.emplace_back(done, total); };
  REQUIRE(runMachine(e.mechanism, e.dynamics, machineDefaultsOf(sweepGridOf(e)), request, control).ok());
  REQUIRE(seen.size() >= 2);
  CHECK(seen.front().first == 0);
  CHECK(seen.back().first == seen.back().second);
  const std::atomic<bool> cancelled{true};
  control.cancel = &cancelled;
  const auto stopped = runMachine(e.mechanism, e.dynamics, machineDefaultsOf(sweepGridOf(e)), request, control);
  REQUIRE_FALSE(stopped.ok());
  CHECK(stopped.error().code == ErrorCode::Cancelled);
}

TEST_CASE("machine's fields refuse what they cannot hold, spelled for the front end that took it",
          "[dynamics][machine][request]") {
  struct Case {
    RequestValues values;
    FrontEnd frontEnd;
    std::string message;
  };
  const std::vector<Case> cases{
      {{{"efficiency", 5e-324}}, FrontEnd::Cli, "--efficiency must be from 0.01 to 1 (got 5e-324)"},
      {{{"efficiency", 1.2}}, FrontEnd::Python, "efficiency must be from 0.01 to 1 (got 1.2)"},
      {{{"efficiency", 0.0}}, FrontEnd::Designer, "Efficiency must be from 0.01 to 1 (got 0)"},
      {{{"cs", 1.0}}, FrontEnd::Cli, "--cs must be from 1e-5 to 0.9 (got 1)"},
      {{{"gear_ratio", -3.0}}, FrontEnd::Python, "gear_ratio must be from 1e-6 to 1e6 (got -3)"},
      {{{"rated_speed", 0.0}}, FrontEnd::Cli, "--rated-speed must be above 0 and at most 1e7 rpm (got 0 rpm)"},
      {{{"rated_torque", 1e300}}, FrontEnd::Cli, "--rated-torque must be above 0 and at most 1e9 N·m (got 1e+300 N·m)"},
      {{{"samples", 3.0}}, FrontEnd::Cli, "--samples must be a whole number from 4 to 100000 (got 3)"},
      {{{"samples", 360.5}}, FrontEnd::Python, "samples must be a whole number from 4 to 100000 (got 360.5)"},
      {{{"omega", 0.0}}, FrontEnd::Cli, "--omega must be from -900000 to 900000 rad/s, not 0 (got 0 rad/s)"},
      {{{"rpm", 10.0}, {"omega", 1.0}}, FrontEnd::Python, "rpm and omega are one speed: give one of them"},
      {{{"tolerance", 0.0}}, FrontEnd::Cli, "--tolerance must be from 1e-12 to 0.01 (got 0)"},
      {{{"radius", 1.0}}, FrontEnd::Cli, "no field 'radius' in this request"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.message);
    const auto r = machineRequest(c.values, c.frontEnd);
    REQUIRE_FALSE(r.ok());
    CHECK(r.error().message == c.message);
  }
  // A motion law in time: a turn's duty needs a constant speed asked for.
  const Example boom = findExample("piston-driven").value();
  MachineDefaults timed = machineDefaultsOf(sweepGridOf(boom));
  CHECK(timed.timeBase);
  const Example e = withMasses("funsho-fourbar");
  const auto refused = runMachine(e.mechanism, e.dynamics, timed, machineRequest({}, FrontEnd::Python).value());
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message.ends_with("give rpm or omega"));
}

TEST_CASE("every machine field has its help, its unit where it has one, and a range that holds its default",
          "[dynamics][machine][request]") {
  for (const RequestField& f : machineFields()) {
    CAPTURE(f.key);
    CHECK_FALSE(f.help.empty());
    CHECK_FALSE(f.label.empty());
    CHECK(f.minimum < f.maximum);
    if (f.value) CHECK_FALSE(checkField(f, *f.value, FrontEnd::Cli));
    CHECK(helpText(f).find(rangeText(f)) != std::string::npos);
  }
  CHECK(fieldName(*findField(machineFields(), "rated_speed"), FrontEnd::Cli) == "--rated-speed");
  CHECK(fieldName(*findField(machineFields(), "rated_speed"), FrontEnd::Python) == "rated_speed");
  CHECK(fieldName(*findField(machineFields(), "rated_speed"), FrontEnd::Designer) == "Rated speed");
}
