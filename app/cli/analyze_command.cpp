#include "app/cli/commands.h"
#include "app/cli/text_table.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/number_format.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <ostream>
#include <sstream>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::ErrorCode;
using kinematics::io::formatShort;

// An input value in the driver's display unit: "30°" for a crank, "12 mm" for a linear driver.
std::string inputText(const kinematics::Mechanism& m, double q) {
  const std::string unit = kinematics::inputUnit(m);
  return formatShort(kinematics::inputDisplayValue(m, q)) + (unit == "°" ? unit : " " + unit);
}

std::string rangesText(const kinematics::Mechanism& m, const std::vector<kinematics::AngleRange>& ranges) {
  std::string text;
  for (const auto& r : ranges) {
    if (!text.empty()) text += ", ";
    text += r.from == r.to ? inputText(m, r.from) : inputText(m, r.from) + " to " + inputText(m, r.to);
  }
  return text;
}

// "crank angles", "tip path positions", "actuator A–C lengths".
std::string inputsName(const kinematics::Mechanism& m) {
  std::string name = kinematics::inputName(m);
  return name.ends_with("position") || name.ends_with("length") || name.ends_with("angle") ? name + "s" : name;
}

void reportUnassembled(const kinematics::SweepResult& result, const ResolvedMechanism& resolved, std::ostream& err) {
  const kinematics::Mechanism& m = resolved.mechanism;
  std::size_t failed = 0;
  for (std::size_t j = 0; j < result.size(); ++j) failed += result.assembled(j) ? 0 : 1;
  err << "linkwright-cli: the linkage cannot be assembled at " << failed << " of " << result.size() << " requested "
      << inputsName(m) << " (" << rangesText(m, result.notAssembled) << "); those rows are left out.\n";
  if (result.firstFailure) err << "  " << *result.firstFailure << ".\n";
  if (!kinematics::asFourBar(resolved.mechanism)) return;
  const kinematics::InputRange range = kinematics::analyseDesign(resolved.mechanism, {}).inputRange;
  if (range.ranges.empty()) err << "  It cannot be assembled at any " << kinematics::inputName(m) << ".\n";
  else err << "  It can be assembled for " << inputsName(m) << " " << rangesText(m, range.ranges) << " (exact).\n";
}

// The forces the invocation asks for, or the reason there are none.
kinematics::Result<std::optional<kinematics::ForceSweep>> forcesFor(const Invocation& inv,
                                                                    const SweptMechanism& swept) {
  if (!inv.forces) return std::optional<kinematics::ForceSweep>{};
  const ResolvedMechanism& r = swept.resolved;
  if (r.dynamics.empty())
    return Error{ErrorCode::InvalidValue, "--forces",
                 "--forces needs masses and loads, and " + r.source +
                     " has none: give them in a document's \"dynamics\" (see docs/document_format.md), or try "
                     "--example funsho-fourbar"};
  auto forces = kinematics::sweepForces(r.mechanism, r.dynamics, swept.result);
  if (!forces) return Error{forces.error().code, "--forces", "--forces: " + forces.error().message};
  return std::optional<kinematics::ForceSweep>{std::move(*forces)};
}

// A sample in the driver's own words: "crank angle 30°", "C path position 12 mm", with its
// instant first on a time base.
std::string sampleText(const kinematics::Mechanism& m, const kinematics::SweepResult& result, std::size_t j) {
  const std::string unit = kinematics::inputUnit(m);
  const std::string input = kinematics::inputName(m) + " " +
                            formatShort(kinematics::inputDisplayValue(m, result.inputAngle[j])) +
                            (unit == "°" ? unit : " " + unit);
  if (result.time.empty()) return input;
  return "time " + formatShort(result.time[j]) + " s (" + input + ")";
}

// Why a toggle has no rates: a four-bar's coupler and output link (its rocker, or its crank
// when driven from the rocker) are collinear; any other linkage has a dyad stretched or folded.
std::string toggleText(const kinematics::Mechanism& m) {
  const auto linkName = [&m](kinematics::PointId a, kinematics::PointId b) -> std::string {
    for (const kinematics::Link& link : m.links)
      if ((link.first == a && link.second == b) || (link.first == b && link.second == a)) return link.name;
    return m.points[a.index].name + "–" + m.points[b.index].name;
  };
  if (const auto f = kinematics::asFourBar(m))
    return linkName(f->b, f->c) + " and " + linkName(f->o4, f->c) + " are collinear, ω and α are undefined";
  return "a dyad is stretched straight or folded, its rates are undefined";
}

// Samples whose kinematics exist but whose forces do not (a structure that locks there).
void reportUndeterminedForces(const kinematics::Mechanism& m, const kinematics::SweepResult& result,
                              const kinematics::ForceSweep& forces, std::ostream& err) {
  for (std::size_t j = 0; j < result.size(); ++j)
    if (result.ok(j) && !forces.ok(j))
      err << "linkwright-cli: note: the joint forces are not determined at " << sampleText(m, result, j)
          << " (the Newton–Euler system is singular; force cells left empty)\n";
}

}  // namespace

void noteLocks(const kinematics::Mechanism& m, const kinematics::SweepResult& sweep, std::ostream& err) {
  for (const kinematics::AngleRange& step : sweep.lockedBetween)
    err << "linkwright-cli: note: the linkage locks between " << inputsName(m) << " " << inputText(m, step.from)
        << " and " << inputText(m, step.to) << " (a dyad passes its assembly limit between these samples); from "
        << inputText(m, step.to) << " on it is assembled afresh on the chosen branches, so points jump there\n";
}

ExitCode runAnalyze(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const Error& e) {
    err << "linkwright-cli: " << e.message << "\n";
    return ExitCode::BadInput;
  };
  const auto swept = sweepInvocation(inv);
  if (!swept) return fail(swept.error());
  const kinematics::Mechanism* mechanism = &swept->resolved.mechanism;
  const kinematics::SweepResult* result = &swept->result;
  const auto forces = forcesFor(inv, *swept);
  if (!forces) return fail(forces.error());
  const kinematics::ForceSweep* forceSweep = forces->has_value() ? &**forces : nullptr;

  std::ostringstream csv;
  if (inv.tableFormat) writeSweepTable(csv, *mechanism, *result, forceSweep);
  else if (forceSweep) kinematics::io::writeSweepCsv(csv, *mechanism, *result, *forceSweep);
  else kinematics::io::writeSweepCsv(csv, *mechanism, *result);
  if (inv.outputFile) {
    if (auto problem = kinematics::io::writeFileSafely(*inv.outputFile, csv.str())) {
      err << "linkwright-cli: " << problem->message << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << csv.str() << std::flush;
  }
  for (const double q : result->singularAngles)
    err << "linkwright-cli: note: toggle position at " << kinematics::inputName(*mechanism) << " "
        << inputText(*mechanism, q) << ": " << toggleText(*mechanism) << " (cells left empty)\n";
  noteLocks(*mechanism, *result, err);
  if (forceSweep) reportUndeterminedForces(*mechanism, *result, *forceSweep, err);
  if (!result->notAssembled.empty()) {
    reportUnassembled(*result, swept->resolved, err);
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
