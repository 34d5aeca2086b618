// `linkwright-cli balance`: the design with counterweights that balance its shaking force
// (kinematics/dynamics/force_balance.h), written as a new document, and what the balance gains
// and costs over one crank turn: the shaking force and moment, the driving torque and the
// bearing loads before and after (kinematics/dynamics/machine_duty.h). With --spring, the
// spring between two points that makes the RMS driving torque least
// (kinematics/dynamics/spring_balance.h) instead.

#include "app/cli/commands.h"

#include "kinematics/dynamics/force_balance.h"
#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/dynamics/spring_balance.h"
#include "kinematics/dynamics/spring_search.h"
#include "kinematics/io/document_json.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"

#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using k::formatShort;

void printComparison(std::ostream& out, const k::MachineDuty& before, const k::MachineDuty& after) {
  const auto row = [&](const std::string& name, double a, double b, const std::string& unit) {
    const std::string change = a > 0.0 ? " (" + formatShort(100.0 * (b - a) / a, 3) + " %)" : "";
    out << "  " << name << formatShort(a, 5) << " → " << formatShort(b, 5) << " " << unit << change << "\n";
  };
  out << "over one crank turn at " << formatShort(before.omega, 5) << " rad/s, before → after:\n";
  row("shaking force peak    ", before.shakingForcePeak, after.shakingForcePeak, "N");
  row("shaking moment peak   ", before.shakingMomentPeak, after.shakingMomentPeak, "N·m");
  row("driving torque RMS    ", before.rmsTorque, after.rmsTorque, "N·m");
  row("driving torque peak   ", before.peakTorque, after.peakTorque, "N·m");
  row("bearing load peak     ", before.bearingLoadPeak, after.bearingLoadPeak, "N");
}

// "crank:B" is a point on a link's body; "S" alone a ground point (the frame).
k::SpringEnd springEnd(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) return {"", text};
  return {text.substr(0, colon), text.substr(colon + 1)};
}

std::string endText(const k::SpringEnd& end) {
  return end.link.empty() ? "the frame at " + end.point : end.point + " on " + end.link;
}

ExitCode balanceBySpring(const Invocation& inv, k::Design design, std::ostream& out, std::ostream& err) {
  const std::string& ends = *inv.springEnds;
  const auto comma = ends.find(',');
  const k::SpringEnd first = springEnd(ends.substr(0, comma)), second = springEnd(ends.substr(comma + 1));
  const auto balance = k::balanceBySpring(design.mechanism, design.dynamics, k::designTurn(design), first, second);
  if (!balance) {
    err << "linkwright-cli: --spring: " << balance.error().message << "\n";
    return ExitCode::BadInput;
  }
  design.dynamics = balance->balanced;
  if (auto e = k::io::writeFileSafely(*inv.outputFile, k::io::writeDocument(design))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  const k::Spring& s = balance->spring;
  out << "spring balance: the spring from " << endText(first) << " to " << endText(second)
      << " that makes the RMS driving torque least; written to " << *inv.outputFile << "\n";
  out << "  stiffness " << formatShort(s.stiffness, 6) << " N/m, free length " << formatShort(s.freeLength, 6) << " "
      << design.mechanism.lengthUnit << ", preload " << formatShort(s.preload, 6) << " N\n";
  out << "over one crank turn at " << formatShort(design.omega, 5) << " rad/s, before → after:\n";
  out << "  driving torque RMS    " << formatShort(balance->rmsBefore, 5) << " → " << formatShort(balance->rmsAfter, 5)
      << " N·m\n";
  return ExitCode::Success;
}

ExitCode balanceBySearchedSpring(const Invocation& inv, k::Design design, std::ostream& out, std::ostream& err) {
  if (inv.springEnds) {
    err << "linkwright-cli: --spring-search: give the spring's ends (--spring) or have them searched "
           "(--spring-search), not both\n";
    return ExitCode::BadInput;
  }
  const auto found =
      k::searchSpringBalance(design.mechanism, design.dynamics, k::designTurn(design), *inv.springSearchLink);
  if (!found) {
    err << "linkwright-cli: --spring-search: " << found.error().message << "\n";
    return ExitCode::BadInput;
  }
  design.mechanism = found->mechanism;
  design.dynamics = found->balance.balanced;
  if (auto e = k::io::writeFileSafely(*inv.outputFile, k::io::writeDocument(design))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  const k::SpringBalance& b = found->balance;
  const std::string& unit = design.mechanism.lengthUnit;
  out << "spring balance: the spring from a point on " << *inv.springSearchLink
      << " to a point on the frame, both searched, that makes the RMS driving torque least; written to "
      << *inv.outputFile << "\n";
  out << "  on " << *inv.springSearchLink << ": " << b.spring.first.point << " at "
      << formatShort(found->onLink.along, 6) << " " << unit << " along and " << formatShort(found->onLink.across, 6)
      << " " << unit << " across the link\n";
  out << "  on the frame: " << b.spring.second.point << " at (" << formatShort(found->onFrame.x(), 6) << ", "
      << formatShort(found->onFrame.y(), 6) << ") " << unit << "\n";
  if (found->atBound)
    out << "  (an end is at the edge of the search, half the link's length off it or a quarter of the linkage's "
           "size outside the box it sweeps: an end allowed further out might do better)\n";
  out << "  stiffness " << formatShort(b.spring.stiffness, 6) << " N/m, free length "
      << formatShort(b.spring.freeLength, 6) << " " << unit << ", preload " << formatShort(b.spring.preload, 6)
      << " N\n";
  out << "over one crank turn at " << formatShort(design.omega, 5) << " rad/s, before → after:\n";
  out << "  driving torque RMS    " << formatShort(b.rmsBefore, 5) << " → " << formatShort(b.rmsAfter, 5) << " N·m\n";
  return ExitCode::Success;
}

}  // namespace

ExitCode runBalance(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveDesign(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  k::Design design = *resolved;
  if (inv.springSearchLink) return balanceBySearchedSpring(inv, std::move(design), out, err);
  if (inv.springEnds) return balanceBySpring(inv, std::move(design), out, err);
  k::BalanceOptions options;
  options.reciprocatingFraction = inv.reciprocatingFraction.value_or(options.reciprocatingFraction);
  options.radius = inv.counterweightRadius.value_or(options.radius);
  const auto balance = k::balanceShakingForce(design.mechanism, design.dynamics, options);
  if (!balance) {
    const std::string& field = balance.error().field;
    const std::string option = field == "fraction" ? "--fraction: " : field == "radius" ? "--radius: " : "";
    err << "linkwright-cli: " << option << balance.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::LinkageDynamics original = design.dynamics;
  design.dynamics = balance->balanced;
  if (auto e = k::io::writeFileSafely(*inv.outputFile, k::io::writeDocument(design))) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  const std::string& unit = design.mechanism.lengthUnit;
  out << balance->method << "; written to " << *inv.outputFile << "\n";
  for (const k::Counterweight& c : balance->counterweights)
    out << "  counterweight on " << c.link << ": " << formatShort(c.mass, 6) << " kg at "
        << formatShort(c.centre.along, 6) << " " << unit << " along and " << formatShort(c.centre.across, 6) << " "
        << unit << " across the link, joined to its mass\n";
  if (balance->counterweights.empty()) out << "  no counterweight needed: it is balanced already\n";
  const k::SweepSpec turn = k::designTurn(design);
  const auto before = k::machineDuty(design.mechanism, original, turn, {});
  const auto after = k::machineDuty(design.mechanism, design.dynamics, turn, {});
  if (before && after) printComparison(out, *before, *after);
  else out << "no turn to compare over: " << (before ? after.error() : before.error()).message << "\n";
  return ExitCode::Success;
}

}  // namespace linkwright::cli
