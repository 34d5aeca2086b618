// `linkwright-cli machine`: what one crank turn asks of the machine, as the core's one request
// (kinematics/dynamics/machine_request.h): its options are the request's fields, its figures the
// core's (dutyFigures), each converged to the request's tolerance or saying its error. Text for
// reading, or the core's JSON in SI units.

#include "app/cli/commands.h"
#include "app/cli/progress.h"

#include "kinematics/design/sweep_grid.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/io/machine_json.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

// The option a core field came from, for messages that name what the user typed.
std::string optionFor(const std::string& key) {
  const k::RequestField* field = k::findField(k::machineFields(), key);
  return field == nullptr ? std::string() : k::fieldName(*field, k::FrontEnd::Cli);
}

std::string accuracyLine(const k::MachineRun& run, const k::MachineRequest& request) {
  const double worst = run.duty.worstAccuracy();
  if (run.duty.accuracy.empty())
    return "no error estimate (an odd number of intervals has no every other sample to compare with)";
  if (run.converged)
    return "every figure within " + k::formatCompact(run.tolerance, 2) + " relative (the largest estimate " +
           k::formatCompact(worst, 2) + ")";
  return std::string(request.samples ? "as asked" : "the finest grid a turn holds") +
         ", the largest error estimate is " + k::formatCompact(worst, 2) + ", over the tolerance " +
         k::formatCompact(run.tolerance, 2) + " (each figure's is beside it)";
}

void printText(std::ostream& out, const k::MachineRun& run, const k::MachineRequest& request,
               const std::string& source) {
  const k::MachineDuty& d = run.duty;
  const k::DutyOptions& o = request.duty;
  const auto n = [](double v) { return formatShort(v, 8); };
  out << "machine duty of " << source << ": one crank turn at " << n(d.omega) << " rad/s ("
      << n(k::radPerSecToRpm(d.omega)) << " rpm), read at " << run.samples << " samples; " << accuracyLine(run, request)
      << "\n";
  std::string group;
  for (const k::DutyFigure& f : k::dutyFigures(d, o)) {
    if (f.group != group) {
      group = f.group;
      out << "motor through the gearbox (ratio " << n(o.gearRatio) << ", efficiency " << n(o.efficiency)
          << "): " << n(k::radPerSecToRpm(d.motor.speed)) << " rpm\n";
    }
    // Padded to a column by characters, not bytes: the labels hold Δ, ² and ω.
    std::string line = "  " + f.label;
    const auto characters = static_cast<std::size_t>(
        std::count_if(line.begin(), line.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
    line += std::string(characters < 47 ? 47 - characters : 1, ' ');
    line += n(f.value) + " " + f.unit;
    if (f.accuracy && *f.accuracy > run.tolerance)
      line += "  (error estimate " + k::formatCompact(*f.accuracy, 2) + ")";
    out << line << "\n";
  }
  if (d.flywheelRun)
    out << "flywheel check      a turn run in time with that flywheel and the mean torque: the speed varies by Cs "
        << n(d.flywheelRun->speedFluctuation) << " between " << n(k::radPerSecToRpm(d.flywheelRun->slowest()))
        << " and " << n(k::radPerSecToRpm(d.flywheelRun->fastest())) << " rpm\n";
  out << "virtual-work check  the driving torque by virtual work is within " << formatShort(d.virtualWorkDifference, 2)
      << " N·m of the Newton–Euler one at every sample\n";
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
  const auto request = k::machineRequest(inv.requestValues, k::FrontEnd::Cli);
  if (!request) {
    err << "linkwright-cli: " << request.error().message << "\n";
    return ExitCode::BadInput;
  }
  Progress progress(err, "machine", "grids");
  k::RunControl control;
  control.progress = [&](std::size_t done, std::size_t total) { progress.update(done, total); };
  const auto run = k::runMachine(resolved->mechanism, resolved->dynamics, k::machineDefaultsOf(resolved->defaults),
                                 *request, control);
  if (!run) {
    const k::Error& e = run.error();
    const std::string option = optionFor(e.field);
    err << "linkwright-cli: " << (option.empty() || e.message.starts_with(option) ? "" : option + ": ") << e.message
        << "\n";
    return e.code == k::ErrorCode::NotAssemblable || e.code == k::ErrorCode::Singular ? ExitCode::NotAssemblable
                                                                                      : ExitCode::BadInput;
  }
  if (inv.json) out << k::io::machineJson(*run, *request).dump(2) << "\n";
  else printText(out, *run, *request, resolved->source);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
