#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/text_table.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace linkwright::cli {
namespace {

using kinematics::Error;
using kinematics::ErrorCode;
using kinematics::formatShort;

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

void reportUnassembled(const kinematics::SweepSummary& summary, const ResolvedMechanism& resolved, std::ostream& err) {
  const kinematics::Mechanism& m = resolved.mechanism;
  const std::size_t failed = summary.samples - summary.assembledSamples;
  err << "linkwright-cli: the linkage cannot be assembled at " << failed << " of " << summary.samples << " requested "
      << inputsName(m) << " (" << rangesText(m, summary.notAssembled) << "); those rows are left out.\n";
  if (summary.firstFailure) err << "  " << *summary.firstFailure << ".\n";
  if (!kinematics::asFourBar(resolved.mechanism)) return;
  const kinematics::InputRange range = kinematics::analyseDesign(resolved.mechanism, {}).inputRange;
  if (range.ranges.empty()) err << "  It cannot be assembled at any " << kinematics::inputName(m) << ".\n";
  else err << "  It can be assembled for " << inputsName(m) << " " << rangesText(m, range.ranges) << " (exact).\n";
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

// Samples whose kinematics exist but whose forces do not (a structure that locks there),
// gathered window by window: the first few named, the rest counted, so that a table of 10⁷ rows
// keeps no more than that.
class UndeterminedForces {
public:
  void gather(const kinematics::Mechanism& m, const kinematics::SweepResult& part,
              const kinematics::ForceSweep& forces) {
    for (std::size_t j = 0; j < part.size(); ++j) {
      if (!part.ok(j) || forces.ok(j)) continue;
      if (m_named.size() < kNamed) m_named.push_back(sampleText(m, part, j));
      else ++m_more;
    }
  }
  void report(std::ostream& err) const {
    for (const std::string& at : m_named)
      err << "linkwright-cli: note: the joint forces are not determined at " << at
          << " (the Newton–Euler system is singular; force cells left empty)\n";
    if (m_more > 0) err << "linkwright-cli: note: … and at " << m_more << " more samples (force cells left empty)\n";
  }

private:
  static constexpr std::size_t kNamed = 20;
  std::vector<std::string> m_named;
  std::size_t m_more = 0;
};

}  // namespace

void noteLocks(const kinematics::Mechanism& m, const std::vector<kinematics::AngleRange>& lockedBetween,
               std::ostream& err) {
  for (const kinematics::AngleRange& step : lockedBetween)
    err << "linkwright-cli: note: the linkage locks between " << inputsName(m) << " " << inputText(m, step.from)
        << " and " << inputText(m, step.to) << " (a dyad passes its assembly limit between these samples); from "
        << inputText(m, step.to) << " on it is assembled afresh on the chosen branches, so points jump there\n";
}

ExitCode runAnalyze(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto fail = [&](const Error& e) {
    err << "linkwright-cli: " << e.message << "\n";
    return ExitCode::BadInput;
  };
  const auto resolved = resolveMechanism(inv);
  if (!resolved) return fail(resolved.error());
  const auto spec = sweepSpecFor(inv, resolved->defaults);
  if (!spec) return fail(spec.error());
  const kinematics::Mechanism& m = resolved->mechanism;
  if (inv.forces && resolved->dynamics.empty())
    return fail(Error{ErrorCode::InvalidValue, "--forces",
                      "--forces needs masses and loads, and " + resolved->source +
                          " has none: give them in a document's \"dynamics\" (see docs/document_format.md), or try "
                          "--example funsho-fourbar"});

  // The sweep is solved and written a window at a time: memory does not grow with the samples.
  std::optional<Error> refused;  // the core's, as opposed to the output's
  kinematics::SweepSummary summary;
  UndeterminedForces undetermined;
  Progress progress(err, "analyze", "samples", progressShown(err, inv.outputFile ? nullptr : &out));
  const auto writeTable = [&](std::ostream& to) -> std::optional<std::string> {
    kinematics::io::SweepCsvWriter csv(to, m);
    SweepTableWriter table(to, m);
    auto swept = kinematics::sweepInWindows(
        m, *spec, {}, kSweepWindowSamples, [&](const kinematics::SweepResult& part, std::size_t first) {
          std::optional<kinematics::ForceSweep> forces;
          if (inv.forces) {
            auto solved = kinematics::sweepForces(m, resolved->dynamics, part);
            if (!solved) {
              refused = Error{solved.error().code, "--forces", "--forces: " + solved.error().message};
              return false;
            }
            forces = std::move(solved).value();
            undetermined.gather(m, part, *forces);
          }
          if (inv.tableFormat) table.write(part, forces ? &*forces : nullptr);
          else csv.write(part, forces ? &*forces : nullptr);
          progress.update(first + part.size(), spec->samples);
          return static_cast<bool>(to);  // a failed write stops the sweep; the writer says why
        });
    if (swept) summary = std::move(swept).value();
    else if (!refused && swept.error().code != ErrorCode::Cancelled) refused = swept.error();
    if (refused) return refused->message;
    return std::nullopt;
  };
  if (inv.outputFile) {
    const auto problem = kinematics::io::writeStreamSafely(*inv.outputFile, writeTable);
    if (refused) return fail(*refused);
    if (problem) {
      err << "linkwright-cli: " << problem->message << "\n";
      return ExitCode::IoError;
    }
  } else {
    writeTable(out);
    out << std::flush;
    if (refused) return fail(*refused);
  }
  for (const double q : summary.singularAngles)
    err << "linkwright-cli: note: toggle position at " << kinematics::inputName(m) << " " << inputText(m, q) << ": "
        << toggleText(m) << " (cells left empty)\n";
  noteLocks(m, summary.lockedBetween, err);
  undetermined.report(err);
  if (!summary.notAssembled.empty()) {
    reportUnassembled(summary, *resolved, err);
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
