// A turn's duty (machine_duty.h) and the flywheel's forward-dynamics check (flywheel_run.h):
// closed forms for a crank carrying a mass under gravity, a printed textbook flywheel, and the
// funsho four-bar's flywheel run against the Cs it was sized for.

#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/design/examples.h"
#include "kinematics/dynamics/flywheel.h"
#include "kinematics/model/driven_linkages.h"
#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"

#include "tests/support/catch.h"

#include <cmath>
#include <limits>
#include <numbers>

using namespace linkwright::kinematics;

namespace {

constexpr double kTurn = 2.0 * std::numbers::pi;

SweepSpec turnAt(double omega, std::size_t samples = 361) { return SweepSpec{0.0, kTurn, samples, omega, 0.0}; }

// The thesis crank-rocker in mm with one mass m at the crank's tip (r = 25 mm) under gravity,
// the coupler and rocker massless: the crank needs T(θ) = m g r cos θ at any constant speed, so
// T̄ = 0, RMS = m g r/√2 and ΔE = 2 m g r (the surplus E(θ) = −m g r sin θ).
struct WeightedCrank {
  Mechanism mechanism;
  LinkageDynamics dynamics;
  double mgr = 0.0;  // N·m
};

WeightedCrank weightedCrank(double mass) {
  WeightedCrank w{makeFourBar({60.0, 25.0, 70.0, 45.0}, Branch::Open).value(), {}, 0.0};
  w.dynamics.links.push_back({"crank", mass, LinkFramePoint{25.0, 0.0}, 0.0});
  w.dynamics.loads.gravity = standardGravity();
  w.mgr = mass * kStandardGravity * 0.025;
  return w;
}

CrankTerms terms(const Mechanism& m, const LinkageDynamics& d, const SweepSpec& turn) {
  const auto moving = turnForces(m, d, turn, turn.omega, 0.0);
  REQUIRE(moving.ok());
  auto t = crankTerms(m, d, turn, moving->forces);
  REQUIRE(t.ok());
  return *t;
}

}  // namespace

TEST_CASE("a weighted crank's duty matches its closed form", "[dynamics][machine]") {
  const WeightedCrank w = weightedCrank(40.0);
  const double omega = rpmToRadPerSec(60.0);
  DutyOptions options;
  options.speedFluctuation = 0.05;
  const auto d = machineDuty(w.mechanism, w.dynamics, turnAt(omega), options);
  REQUIRE(d.ok());
  REQUIRE(d->torque.size() == 361);
  for (std::size_t j = 0; j < d->torque.size(); ++j)
    CHECK(d->torque[j] == Approx(w.mgr * std::cos(d->angle[j])).margin(1e-12 * w.mgr));
  CHECK(d->meanTorque == Approx(0.0).margin(1e-12 * w.mgr));
  CHECK(d->peakTorque == Approx(w.mgr).epsilon(1e-12));
  CHECK(d->peakPower == Approx(w.mgr * omega).epsilon(1e-12));
  CHECK(d->virtualWorkDifference <= 1e-12 * w.mgr);
  // Read off the samples' series, the integrals are exact to round-off (the trapezoidal rule's
  // running sum was h²/12 ≈ 2.5e-5 out at 1°).
  CHECK(d->rmsTorque == Approx(w.mgr / std::sqrt(2.0)).epsilon(1e-13));
  CHECK(d->energyFluctuation == Approx(2.0 * w.mgr).epsilon(1e-13));
  REQUIRE(d->flywheelInertia);
  CHECK(*d->textbookFlywheelInertia == Approx(2.0 * w.mgr / (0.05 * omega * omega)).epsilon(1e-13));
  // The crank's own inertia m r² turns with the flywheel at every angle: it counts in full.
  CHECK(*d->flywheelInertia == Approx(*d->textbookFlywheelInertia - 40.0 * 0.025 * 0.025).epsilon(1e-3));
  for (std::size_t j = 0; j < d->energy.size(); ++j)
    CHECK(d->energy[j] == Approx(-w.mgr * std::sin(d->angle[j])).margin(1e-13 * w.mgr));
  // Every figure says its error: the same figure off every other sample agrees to round-off.
  CHECK(d->accuracy.size() == 15);
  CHECK(d->worstAccuracy() < 1e-12);
}

TEST_CASE("through a gearbox the motor's torque is T/(N η) where it drives and T η/N where it is driven back",
          "[dynamics][machine]") {
  const WeightedCrank w = weightedCrank(40.0);
  DutyOptions options;
  options.gearRatio = 10.0;
  options.efficiency = 0.8;
  const double omega = rpmToRadPerSec(30.0);
  const auto d = machineDuty(w.mechanism, w.dynamics, turnAt(omega), options);
  REQUIRE(d.ok());
  // Half the turn each way: RMS² = (m g r)²/2 · ((1/(N η))² + (η/N)²)/2. The motor's torque has a
  // kink where T changes sign; split there, its integrals are exact from 361 samples.
  const double n = 10.0, eta = 0.8;
  const double rms = w.mgr * std::sqrt(0.25 * (1.0 / (n * n * eta * eta) + eta * eta / (n * n)));
  CHECK(d->motor.speed == Approx(n * omega));
  CHECK(d->motor.rmsTorque == Approx(rms).epsilon(1e-12));
  CHECK(d->motor.peakTorque == Approx(w.mgr / (n * eta)).epsilon(1e-12));
  CHECK(d->motor.peakPower == Approx(w.mgr * omega / eta).epsilon(1e-12));
  // The motor gives (1/η − η)·(2 m g r ω/2π)/2 more than the linkage takes back: the gearbox's loss.
  CHECK(d->motor.meanPower == Approx((1.0 / eta - eta) * w.mgr * omega / std::numbers::pi).epsilon(1e-12));
  CHECK(d->accuracy.at("motor.rms_torque_Nm") < 1e-12);
  CHECK(d->motor.verdict.empty());
  options.ratedTorque = 0.5 * d->motor.rmsTorque;
  CHECK(machineDuty(w.mechanism, w.dynamics, turnAt(omega), options)->motor.verdict.starts_with("too weak"));
  options.ratedTorque = 2.0 * d->motor.rmsTorque;
  options.ratedSpeed = 0.5 * n * omega;
  CHECK(machineDuty(w.mechanism, w.dynamics, turnAt(omega), options)->motor.verdict.starts_with("too slow"));
  options.ratedSpeed = 2.0 * n * omega;
  CHECK(
      machineDuty(w.mechanism, w.dynamics, turnAt(omega), options)->motor.verdict.starts_with("adequate: RMS torque"));
}

TEST_CASE(
    "Khurmi and Gupta's flywheel: 6.5 t at a radius of gyration of 1.8 m, 120 rpm, ΔE 56 kN·m runs between "
    "119 and 121 rpm",
    "[dynamics][machine]") {
  // R. S. Khurmi and J. K. Gupta, Theory of Machines, ch. 16 (Turning Moment Diagrams and
  // Flywheel), Example 16.1: I = m k² = 6500 · 1.8² kg·m², N = 120 rpm, ΔE = 56 kN·m; the book
  // finds N1 = 121 and N2 = 119 rpm. Here the 56 kJ come from a weighted crank (2 m g r), and
  // the book's flywheel is run by forward dynamics.
  const WeightedCrank w = weightedCrank(56'000.0 / (2.0 * kStandardGravity * 0.025));
  const double omega = rpmToRadPerSec(120.0);
  const double inertia = 6500.0 * 1.8 * 1.8;
  DutyOptions options;
  options.speedFluctuation = (121.0 - 119.0) / 120.0;  // the book's answer, to whole rpm
  const auto d = machineDuty(w.mechanism, w.dynamics, turnAt(omega, 721), options);
  REQUIRE(d.ok());
  CHECK(d->energyFluctuation == Approx(56'000.0).epsilon(1e-5));
  // The book's speeds are rounded to whole rpm (2.02 rpm apart, not 2): 1 %.
  CHECK(*d->textbookFlywheelInertia == Approx(inertia).epsilon(0.011));
  const auto run = runFlywheel(terms(w.mechanism, w.dynamics, turnAt(omega, 721)), inertia);
  REQUIRE(run.ok());
  double low = std::numeric_limits<double>::max(), high = 0.0;
  for (const double s : run->speed) {
    low = std::min(low, s);
    high = std::max(high, s);
  }
  CHECK(std::round(radPerSecToRpm(high)) == 121.0);
  CHECK(std::round(radPerSecToRpm(low)) == 119.0);
  // The crank's own m r² adds to the book's flywheel: ΔE = (I + m r²) ω (ω_max − ω_min).
  const double crank = 56'000.0 / (2.0 * kStandardGravity * 0.025) * 0.025 * 0.025;
  CHECK(high - low == Approx(56'000.0 / ((inertia + crank) * omega)).epsilon(1e-4));
}

TEST_CASE("the funsho four-bar's flywheel, run by forward dynamics, holds the speed within the Cs it was sized for",
          "[dynamics][machine]") {
  const auto e = findExample("funsho-fourbar").value();
  for (const double cs : {0.1, 0.05, 0.02}) {
    CAPTURE(cs);
    DutyOptions options;
    options.speedFluctuation = cs;
    const SweepSpec turn = turnAt(e.omega);
    const auto d = machineDuty(e.mechanism, e.dynamics, turn, options);
    REQUIRE(d.ok());
    REQUIRE(d->energyFluctuation > 0.0);
    const CrankTerms t = terms(e.mechanism, e.dynamics, turn);
    CHECK(flywheelSpeeds(t, *d->flywheelInertia).fluctuation() == Approx(cs).epsilon(1e-10));
    const auto run = runFlywheel(t, *d->flywheelInertia);
    REQUIRE(run.ok());
    CHECK(run->meanSpeed == Approx(e.omega).epsilon(1e-3));
    CHECK(run->speedFluctuation == Approx(cs).epsilon(0.02));
    // The duty carries the same run, and its range is its Cs.
    REQUIRE(d->flywheelRun);
    CHECK(d->flywheelRun->speed == run->speed);
    CHECK((d->flywheelRun->fastest() - d->flywheelRun->slowest()) / std::abs(d->flywheelRun->meanSpeed) ==
          Approx(d->flywheelRun->speedFluctuation).epsilon(1e-12));
    CHECK(d->flywheelRun->slowest() < e.omega);
    CHECK(d->flywheelRun->fastest() > e.omega);
    // The textbook flywheel, which neglects the linkage's inertia, misses Cs by more.
    const auto textbook = runFlywheel(t, *d->textbookFlywheelInertia);
    CHECK(std::abs(textbook->speedFluctuation - cs) > std::abs(run->speedFluctuation - cs));
    CHECK(std::abs(run->angle.back() - run->angle.front()) >= kTurn);
  }
  // The figures do not depend on the grid: 1° against 0.25°, and the 1° grid's own estimates
  // say as much.
  const auto coarse = machineDuty(e.mechanism, e.dynamics, turnAt(e.omega, 361), {});
  const auto fine = machineDuty(e.mechanism, e.dynamics, turnAt(e.omega, 1441), {});
  CHECK(coarse->energyFluctuation == Approx(fine->energyFluctuation).epsilon(1e-12));
  CHECK(coarse->rmsTorque == Approx(fine->rmsTorque).epsilon(1e-12));
  CHECK(coarse->peakTorque == Approx(fine->peakTorque).epsilon(1e-12));
  CHECK(coarse->shakingForcePeak == Approx(fine->shakingForcePeak).epsilon(1e-12));
  CHECK(coarse->bearingLoadPeak == Approx(fine->bearingLoadPeak).epsilon(1e-12));
  CHECK(coarse->worstAccuracy() < 1e-9);
}

TEST_CASE("a turn's duty refuses what it cannot compute, naming the field", "[dynamics][machine]") {
  const WeightedCrank w = weightedCrank(1.0);
  const auto refused = [&](const SweepSpec& turn, const DutyOptions& o) {
    const auto d = machineDuty(w.mechanism, w.dynamics, turn, o);
    REQUIRE_FALSE(d.ok());
    return d.error();
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double cs : {0.0, 1.0, -0.1, nan}) {
    DutyOptions o;
    o.speedFluctuation = cs;
    const Error e = refused(turnAt(1.0), o);
    CHECK(e.field == "cs");
    CHECK(e.message.starts_with("the coefficient of speed fluctuation Cs must be from 1e-5 to 0.9"));
  }
  DutyOptions gear;
  gear.gearRatio = 0.0;
  CHECK(refused(turnAt(1.0), gear).message ==
        "the gear ratio must be from 1e-6 to 1e6 motor turns per crank turn (got 0)");
  for (const double eta : {1.5, 5e-324, 0.0099}) {
    DutyOptions efficiency;
    efficiency.efficiency = eta;
    CHECK(refused(turnAt(1.0), efficiency).field == "efficiency");
  }
  CHECK(refused(SweepSpec{0.0, kTurn / 2.0, 181, 1.0, 0.0}, {}).message ==
        "a turn's duty needs the grid to span one full turn, 360° (got 180°)");
  CHECK(refused(turnAt(0.0), {}).field == "omega");
  CHECK(refused(turnAt(1.0, 100'001), {}).message == "a turn's duty needs 4 to 100000 samples (got 100001)");
  CHECK(refused(SweepSpec{0.0, kTurn, 361, 1.0, 2.0}, {}).field == "alpha");
  // A crank that cannot turn fully (a triple rocker) names where it stops.
  const Mechanism rocker = makeFourBar({60.0, 50.0, 20.0, 45.0}, Branch::Open).value();
  const auto d = machineDuty(rocker, w.dynamics, turnAt(1.0), {});
  REQUIRE_FALSE(d.ok());
  CHECK(d.error().field == "range");
  CHECK(d.error().message.starts_with("the crank cannot turn fully at a constant speed: at "));
  const auto run = runFlywheel(terms(w.mechanism, w.dynamics, turnAt(1.0)), -1.0);
  REQUIRE_FALSE(run.ok());
  CHECK(run.error().field == "flywheel inertia");
}
