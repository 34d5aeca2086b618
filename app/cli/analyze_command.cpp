#include "app/cli/atomic_file.h"
#include "app/cli/commands.h"
#include "app/cli/text_table.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/number_format.h"
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

std::string degreesText(double radians) { return formatShort(kinematics::radToDeg(radians)) + "°"; }

std::string rangesText(const std::vector<kinematics::AngleRange>& ranges) {
  std::string text;
  for (const auto& r : ranges) {
    if (!text.empty()) text += ", ";
    text += r.from == r.to ? degreesText(r.from) : degreesText(r.from) + " to " + degreesText(r.to);
  }
  return text;
}

void reportUnassembled(const kinematics::SweepResult& result, const ResolvedMechanism& resolved, std::ostream& err) {
  std::size_t failed = 0;
  for (std::size_t j = 0; j < result.size(); ++j) failed += result.assembled(j) ? 0 : 1;
  err << "linkwright-cli: the linkage cannot be assembled at " << failed << " of " << result.size()
      << " requested crank angles (" << rangesText(result.notAssembled) << "); those rows are left out.\n";
  if (result.firstFailure) err << "  " << *result.firstFailure << ".\n";
  if (!kinematics::asFourBar(resolved.mechanism)) return;
  const kinematics::InputRange range = kinematics::analyseDesign(resolved.mechanism, {}).inputRange;
  if (range.ranges.empty()) err << "  It cannot be assembled at any crank angle.\n";
  else err << "  It can be assembled for crank angles " << rangesText(range.ranges) << " (exact).\n";
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

// Samples whose kinematics exist but whose forces do not (a structure that locks there).
void reportUndeterminedForces(const kinematics::SweepResult& result, const kinematics::ForceSweep& forces,
                              std::ostream& err) {
  for (std::size_t j = 0; j < result.size(); ++j)
    if (result.ok(j) && !forces.ok(j))
      err << "linkwright-cli: note: the joint forces are not determined at crank angle "
          << degreesText(result.inputAngle[j]) << " (the Newton–Euler system is singular; force cells left empty)\n";
}

}  // namespace

void noteLocks(const kinematics::SweepResult& sweep, std::ostream& err) {
  for (const kinematics::AngleRange& step : sweep.lockedBetween)
    err << "linkwright-cli: note: the linkage locks between crank angles " << degreesText(step.from) << " and "
        << degreesText(step.to) << " (a dyad passes its assembly limit between these samples); from "
        << degreesText(step.to) << " on it is assembled afresh on the chosen branches, so points jump there\n";
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
    if (auto problem = writeFileAtomically(*inv.outputFile, csv.str())) {
      err << "linkwright-cli: " << *problem << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << csv.str() << std::flush;
  }
  for (const double angle : result->singularAngles)
    err << "linkwright-cli: note: toggle position at crank angle " << degreesText(angle)
        << ": coupler and rocker are collinear, ω and α are undefined (cells left empty)\n";
  noteLocks(*result, err);
  if (forceSweep) reportUndeterminedForces(*result, *forceSweep, err);
  if (!result->notAssembled.empty()) {
    reportUnassembled(*result, swept->resolved, err);
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
