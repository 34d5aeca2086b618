// `linkwright-cli machine`: what one crank turn asks of the machine (kinematics/dynamics/
// machine_duty.h): the driving torque's mean, RMS and peak, the power, the energy fluctuation
// and the flywheel for a coefficient of speed fluctuation, the frame's peak shaking force and
// moment, and the motor's duty through a gearbox with a verdict against its rating. Text for
// reading, or one JSON object in SI units; every number comes from the core.

#include "app/cli/commands.h"

#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/io/json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>

#include <cmath>
#include <map>
#include <numbers>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

// The option a core field came from, for messages that name what the user typed.
std::string optionFor(const std::string& field, const Invocation& inv) {
  static const std::map<std::string, std::string> options{{"cs", "--cs"},
                                                          {"gear ratio", "--gear-ratio"},
                                                          {"efficiency", "--efficiency"},
                                                          {"rated torque", "--rated-torque"},
                                                          {"rated speed", "--rated-speed"},
                                                          {"samples", "--samples"}};
  if (field == "omega") return inv.rpm ? "--rpm" : "--omega";
  const auto found = options.find(field);
  return found == options.end() ? std::string() : found->second;
}

// The turn: one full turn from the grid's start, at the document's speed or --rpm/--omega, with
// the grid's step or --samples samples.
k::Result<k::SweepSpec> turnFor(const Invocation& inv, const GridDefaults& d) {
  if (d.time && !inv.rpm && !inv.omega)
    return k::Error{k::ErrorCode::InvalidValue, "--rpm",
                    "machine computes a turn at a constant crank speed, and this linkage's crank follows a motion law "
                    "in time: give --rpm or --omega"};
  k::SweepSpec turn;
  turn.omega = inv.rpm ? k::rpmToRadPerSec(*inv.rpm) : inv.omega.value_or(d.omega);
  turn.fromAngle = k::degToRad(d.fromDeg);
  turn.toAngle = turn.fromAngle + 2.0 * std::numbers::pi;
  // The grid's step, up to the most a turn holds; --samples exactly as asked.
  const auto limit = static_cast<long long>(k::kMaxTurnSamples);
  const long long samples = inv.samples.value_or(std::min(std::llround(360.0 / d.stepDeg) + 1, limit));
  if (samples < 4 || samples > limit)
    return k::Error{k::ErrorCode::InvalidValue, "--samples",
                    "--samples must be between 4 and 100000 for a turn (got " + std::to_string(samples) + ")"};
  turn.samples = static_cast<std::size_t>(samples);
  return turn;
}

k::DutyOptions dutyOptions(const Invocation& inv) {
  k::DutyOptions o;
  o.speedFluctuation = inv.speedFluctuation;
  o.gearRatio = inv.gearRatio.value_or(1.0);
  o.efficiency = inv.efficiency.value_or(1.0);
  o.ratedTorque = inv.ratedTorque;
  if (inv.ratedRpm) o.ratedSpeed = k::rpmToRadPerSec(*inv.ratedRpm);
  return o;
}

void printJson(std::ostream& out, const k::MachineDuty& d, const k::DutyOptions& o, std::size_t samples) {
  k::io::JsonValue json{{"omega_rad_s", d.omega},         {"samples", samples},
                        {"mean_torque_Nm", d.meanTorque}, {"rms_torque_Nm", d.rmsTorque},
                        {"peak_torque_Nm", d.peakTorque}, {"mean_power_W", d.meanPower},
                        {"peak_power_W", d.peakPower},    {"energy_fluctuation_J", d.energyFluctuation}};
  if (d.flywheelInertia) {
    json["cs"] = *o.speedFluctuation;
    json["flywheel_inertia_kg_m2"] = *d.flywheelInertia;
    json["textbook_flywheel_inertia_kg_m2"] = *d.textbookFlywheelInertia;
    json["cs_by_forward_dynamics"] = d.flywheelRun->speedFluctuation;
  }
  json["shaking_force_peak_N"] = d.shakingForcePeak;
  json["shaking_moment_peak_Nm"] = d.shakingMomentPeak;
  json["bearing_load_peak_N"] = d.bearingLoadPeak;
  json["virtual_work_difference_Nm"] = d.virtualWorkDifference;
  k::io::JsonValue motor{
      {"gear_ratio", o.gearRatio},          {"efficiency", o.efficiency},           {"speed_rad_s", d.motor.speed},
      {"rms_torque_Nm", d.motor.rmsTorque}, {"peak_torque_Nm", d.motor.peakTorque}, {"mean_power_W", d.motor.meanPower},
      {"peak_power_W", d.motor.peakPower}};
  if (!d.motor.verdict.empty()) motor["verdict"] = d.motor.verdict;
  json["motor"] = motor;
  out << json.dump(2) << "\n";
}

void printText(std::ostream& out, const k::MachineDuty& d, const k::DutyOptions& o, const std::string& source,
               std::size_t samples) {
  const auto n = [](double v) { return formatShort(v, 5); };
  out << "machine duty of " << source << ": one crank turn at " << n(d.omega) << " rad/s ("
      << n(k::radPerSecToRpm(d.omega)) << " rpm), " << samples << " samples\n";
  out << "driving torque      mean " << n(d.meanTorque) << " N·m, RMS " << n(d.rmsTorque) << " N·m, peak "
      << n(d.peakTorque) << " N·m\n";
  out << "power at the crank  mean " << n(d.meanPower) << " W, peak " << n(d.peakPower) << " W\n";
  out << "energy fluctuation  ΔE " << n(d.energyFluctuation) << " J (the turn's surplus above the mean torque)\n";
  if (d.flywheelInertia)
    out << "flywheel            " << n(*d.flywheelInertia) << " kg·m² on the crank shaft for Cs "
        << n(*o.speedFluctuation) << " (the linkage's own inertia counted; the textbook ΔE/(Cs ω²) gives "
        << n(*d.textbookFlywheelInertia) << " kg·m²)\n"
        << "forward dynamics    a turn run in time with that flywheel and the mean torque: the speed varies by Cs "
        << n(d.flywheelRun->speedFluctuation) << " between " << n(k::radPerSecToRpm(d.flywheelRun->slowest()))
        << " and " << n(k::radPerSecToRpm(d.flywheelRun->fastest())) << " rpm\n";
  out << "frame               shaking force peak " << n(d.shakingForcePeak) << " N, shaking moment peak "
      << n(d.shakingMomentPeak) << " N·m (about the crank's pivot); bearing load peak " << n(d.bearingLoadPeak)
      << " N\n";
  out << "virtual-work check  the driving torque by virtual work is within " << formatShort(d.virtualWorkDifference, 2)
      << " N·m of the Newton–Euler one at every sample\n";
  out << "motor               gear ratio " << n(o.gearRatio) << ", efficiency " << n(o.efficiency) << ": "
      << n(k::radPerSecToRpm(d.motor.speed)) << " rpm, RMS torque " << n(d.motor.rmsTorque) << " N·m, peak "
      << n(d.motor.peakTorque) << " N·m, mean power " << n(d.motor.meanPower) << " W, peak " << n(d.motor.peakPower)
      << " W\n";
  if (!d.motor.verdict.empty()) out << "motor verdict       " << d.motor.verdict << "\n";
}

}  // namespace

ExitCode runMachine(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (auto e = k::checkCrankDriven(resolved->mechanism)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  if (resolved->dynamics.empty()) {
    err << "linkwright-cli: machine needs masses and loads, and " << resolved->source
        << " has none (give them in the designer's Dynamics panel, or in the document: docs/document_format.md)\n";
    return ExitCode::BadInput;
  }
  const auto turn = turnFor(inv, resolved->defaults);
  if (!turn) {
    err << "linkwright-cli: " << turn.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::DutyOptions options = dutyOptions(inv);
  const auto duty = k::machineDuty(resolved->mechanism, resolved->dynamics, *turn, options);
  if (!duty) {
    const k::Error& e = duty.error();
    const std::string option = optionFor(e.field, inv);
    err << "linkwright-cli: " << (option.empty() ? "" : option + ": ") << e.message << "\n";
    return e.code == k::ErrorCode::NotAssemblable || e.code == k::ErrorCode::Singular ? ExitCode::NotAssemblable
                                                                                      : ExitCode::BadInput;
  }
  if (inv.json) printJson(out, *duty, options, turn->samples);
  else printText(out, *duty, options, resolved->source, turn->samples);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
