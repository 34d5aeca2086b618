// `linkwright-cli balance`: the design with counterweights that balance its shaking force
// (kinematics/dynamics/force_balance.h), written as a new document, and what the balance gains
// and costs over one crank turn: the shaking force and moment, the driving torque and the
// bearing loads before and after (kinematics/dynamics/machine_duty.h). With --spring, the
// spring between two points that makes the RMS driving torque least
// (kinematics/dynamics/spring_balance.h) instead. One request for every front end
// (kinematics/design/balance_request.h); text for reading, or the core's JSON.

#include "app/cli/commands.h"

#include "kinematics/design/balance_request.h"
#include "kinematics/dynamics/machine_request.h"
#include "kinematics/io/balance_json.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

void printComparison(std::ostream& out, const k::BalanceRun& run) {
  const k::MachineDuty &before = *run.before, &after = *run.after;
  const auto row = [&](const std::string& name, double a, double b, const std::string& unit) {
    const std::string change = a > 0.0 ? " (" + formatShort(100.0 * (b - a) / a, 3) + " %)" : "";
    out << "  " << name << formatShort(a, 5) << " → " << formatShort(b, 5) << " " << unit << change << "\n";
  };
  out << "over one crank turn at " << formatShort(before.omega, 5) << " rad/s, before → after (" << run.turnSamples
      << " samples, every figure "
      << (run.converged ? "within " + k::formatCompact(k::kMachineTolerance, 1) + " relative"
                        : "to " + k::formatCompact(std::max(before.worstAccuracy(), after.worstAccuracy()), 2) +
                              " relative, not converged")
      << "):\n";
  row("shaking force peak    ", before.shakingForcePeak, after.shakingForcePeak, "N");
  row("shaking moment peak   ", before.shakingMomentPeak, after.shakingMomentPeak, "N·m");
  row("driving torque RMS    ", before.rmsTorque, after.rmsTorque, "N·m");
  row("driving torque peak   ", before.peakTorque, after.peakTorque, "N·m");
  row("bearing load peak     ", before.bearingLoadPeak, after.bearingLoadPeak, "N");
}

std::string endText(const k::SpringEnd& end) {
  return end.link.empty() ? "the frame at " + end.point : end.point + " on " + end.link;
}

void printSpring(std::ostream& out, const k::BalanceRun& run, const Invocation& inv) {
  const k::SpringBalance& b = *run.spring;
  const std::string& unit = run.balanced.mechanism.lengthUnit;
  if (run.placement) {
    const k::SpringPlacement& p = *run.placement;
    out << "spring balance: the spring from a point on " << *inv.springSearchLink
        << " to a point on the frame, both searched, that makes the RMS driving torque least; written to "
        << *inv.outputFile << "\n";
    out << "  on " << *inv.springSearchLink << ": " << b.spring.first.point << " at " << formatShort(p.onLink.along, 6)
        << " " << unit << " along and " << formatShort(p.onLink.across, 6) << " " << unit << " across the link\n";
    out << "  on the frame: " << b.spring.second.point << " at (" << formatShort(p.onFrame.x(), 6) << ", "
        << formatShort(p.onFrame.y(), 6) << ") " << unit << "\n";
    if (p.atBound)
      out << "  (an end is at the edge of the search, half the link's length off it or a quarter of the linkage's "
             "size outside the box it sweeps: an end allowed further out might do better)\n";
  } else {
    out << "spring balance: the spring from " << endText(b.spring.first) << " to " << endText(b.spring.second)
        << " that makes the RMS driving torque least; written to " << *inv.outputFile << "\n";
  }
  out << "  stiffness " << formatShort(b.spring.stiffness, 6) << " N/m, free length "
      << formatShort(b.spring.freeLength, 6) << " " << unit << ", preload " << formatShort(b.spring.preload, 6)
      << " N\n";
  out << "over one crank turn at " << formatShort(run.balanced.omega, 5) << " rad/s, before → after:\n";
  out << "  driving torque RMS    " << formatShort(b.rmsBefore, 5) << " → " << formatShort(b.rmsAfter, 5) << " N·m\n";
}

void printWeights(std::ostream& out, const k::BalanceRun& run, const Invocation& inv) {
  const std::string& unit = run.balanced.mechanism.lengthUnit;
  out << run.weights->method << "; written to " << *inv.outputFile << "\n";
  for (const k::Counterweight& c : run.weights->counterweights)
    out << "  counterweight on " << c.link << ": " << formatShort(c.mass, 6) << " kg at "
        << formatShort(c.centre.along, 6) << " " << unit << " along and " << formatShort(c.centre.across, 6) << " "
        << unit << " across the link, joined to its mass\n";
  if (run.weights->counterweights.empty()) out << "  no counterweight needed: it is balanced already\n";
  if (run.before && run.after) printComparison(out, run);
  else out << "no turn to compare over: " << run.noTurn << "\n";
}

}  // namespace

ExitCode runBalance(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto design = resolveDesign(inv);
  if (!design) {
    err << "linkwright-cli: " << design.error().message << "\n";
    return ExitCode::BadInput;
  }
  const auto run = k::runBalance(*design, balanceRequestOf(inv));
  if (!run) {
    err << "linkwright-cli: " << run.error().message << "\n";
    return ExitCode::BadInput;
  }
  if (auto e = k::io::writeFileSafely(*inv.outputFile, k::io::writeDocument(run->balanced))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  if (inv.json) out << k::io::balanceJson(*run, *inv.outputFile).dump(2) << "\n";
  else if (run->spring) printSpring(out, *run, inv);
  else printWeights(out, *run, inv);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
