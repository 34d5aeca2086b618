#include "kinematics/dynamics/machine_request.h"

#include "kinematics/model/units.h"

#include <cmath>
#include <numbers>

namespace linkwright::kinematics {
namespace {

using Kind = RequestField::Kind;

// The crank's speed either way, within the core's |ω| ≤ 1e6 rad/s, in round numbers.
constexpr double kMostRpm = 9e6;
constexpr double kMostOmega = 9e5;

std::optional<double> given(const RequestValues& values, const char* key) {
  const auto found = values.find(key);
  return found == values.end() ? std::nullopt : std::optional<double>(found->second);
}

}  // namespace

const std::vector<RequestField>& machineFields() {
  static const std::vector<RequestField> fields{
      {"rpm", "Crank speed", "rpm", Kind::Number, -kMostRpm, kMostRpm, true, true, true, std::nullopt, "the design's",
       "the crank's constant speed, instead of omega"},
      {"omega", "Crank speed", "rad/s", Kind::Number, -kMostOmega, kMostOmega, true, true, true, std::nullopt,
       "the design's", "the crank's constant speed"},
      {"samples", "Samples", "", Kind::Count, 4.0, static_cast<double>(kMaxTurnSamples), true, true, false,
       std::nullopt, "chosen for the tolerance",
       "samples over the turn, both ends counted, read exactly as given (the figures then say their error)"},
      {"tolerance", "Tolerance", "", Kind::Number, 1e-12, 1e-2, true, true, false, kMachineTolerance, "",
       "the relative error every figure is computed to: the turn is sampled more finely until each one's "
       "estimate is within it"},
      {"cs", "Cs", "", Kind::Number, kMinSpeedFluctuation, kMaxSpeedFluctuation, true, true, false, std::nullopt,
       "none: no flywheel", "size a flywheel for the coefficient of speed fluctuation Cs = (ω_max − ω_min)/ω"},
      {"gear_ratio", "Gear ratio", "", Kind::Number, 1.0 / kMaxGearRatio, kMaxGearRatio, true, true, false, 1.0, "",
       "motor turns per crank turn"},
      {"efficiency", "Efficiency", "", Kind::Number, kMinEfficiency, 1.0, true, true, false, 1.0, "",
       "the gearbox's efficiency"},
      {"rated_torque", "Rated torque", "N·m", Kind::Number, 0.0, kMaxRatedTorque, false, true, false, std::nullopt,
       "none", "the motor's rated continuous torque: a verdict on its duty"},
      {"rated_speed", "Rated speed", "rpm", Kind::Number, 0.0, kMaxRatedRpm, false, true, false, std::nullopt, "none",
       "the motor's rated speed"},
  };
  return fields;
}

Result<MachineRequest> machineRequest(const RequestValues& values, FrontEnd frontEnd) {
  const auto& fields = machineFields();
  if (auto e = checkValues(fields, values, frontEnd)) return *e;
  const auto rpm = given(values, "rpm"), omega = given(values, "omega");
  if (rpm && omega)
    return Error{ErrorCode::InvalidValue, "rpm",
                 fieldName(*findField(fields, "rpm"), frontEnd) + " and " +
                     fieldName(*findField(fields, "omega"), frontEnd) + " are one speed: give one of them"};
  MachineRequest r;
  r.frontEnd = frontEnd;
  if (rpm) r.omega = rpmToRadPerSec(*rpm);
  if (omega) r.omega = *omega;
  if (const auto n = given(values, "samples")) r.samples = static_cast<std::size_t>(*n);
  r.tolerance = given(values, "tolerance").value_or(kMachineTolerance);
  r.duty.speedFluctuation = given(values, "cs");
  r.duty.gearRatio = given(values, "gear_ratio").value_or(1.0);
  r.duty.efficiency = given(values, "efficiency").value_or(1.0);
  r.duty.ratedTorque = given(values, "rated_torque");
  if (const auto speed = given(values, "rated_speed")) r.duty.ratedSpeed = rpmToRadPerSec(*speed);
  return r;
}

Result<MachineRun> runMachine(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                              const MachineDefaults& defaults, const MachineRequest& request,
                              const RunControl& control) {
  const auto turnOf = [&](std::size_t samples) {
    const double omega = request.omega.value_or(defaults.omega);
    return SweepSpec{defaults.fromAngle, defaults.fromAngle + 2.0 * std::numbers::pi, samples, omega, 0.0};
  };
  if (defaults.timeBase && !request.omega) {
    const auto& fields = machineFields();
    return Error{ErrorCode::InvalidValue, "rpm",
                 "machine computes a turn at a constant crank speed, and this linkage's crank follows a motion law "
                 "in time: give " +
                     fieldName(*findField(fields, "rpm"), request.frontEnd) + " or " +
                     fieldName(*findField(fields, "omega"), request.frontEnd)};
  }
  MachineRun run;
  run.tolerance = request.tolerance;
  if (request.samples) {
    auto duty = machineDuty(mechanism, dynamics, turnOf(*request.samples), request.duty, control.cancel);
    if (!duty) return duty.error();
    run.duty = std::move(duty).value();
    run.samples = *request.samples;
    run.converged = !run.duty.accuracy.empty() && run.duty.worstAccuracy() <= request.tolerance;
    return run;
  }
  std::size_t grids = 0;
  for (std::size_t n = kMachineFirstIntervals; n + 1 <= kMaxTurnSamples; n *= 2) ++grids;
  std::size_t intervals = kMachineFirstIntervals;
  for (std::size_t grid = 0; grid < grids; ++grid, intervals *= 2) {
    if (control.cancelled()) return cancelledError();
    if (control.progress) control.progress(grid, grids);
    auto duty = machineDuty(mechanism, dynamics, turnOf(intervals + 1), request.duty, control.cancel);
    if (!duty) return duty.error();
    run.duty = std::move(duty).value();
    run.samples = intervals + 1;
    run.converged = run.duty.worstAccuracy() <= request.tolerance;
    if (run.converged) break;
  }
  if (control.progress) control.progress(grids, grids);
  return run;
}

}  // namespace linkwright::kinematics
