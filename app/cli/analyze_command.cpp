#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/text_table.h"

#include "kinematics/design/sweep_notes.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/io/csv_writer.h"
#include "kinematics/io/safe_file.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
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

// The samples left out, as the core words them (kinematics/design/sweep_notes.h): the first
// sentence after the program's name, the rest indented beneath it.
void reportUnassembled(const kinematics::SweepSummary& summary, const kinematics::Mechanism& m, std::ostream& err) {
  bool first = true;
  for (const std::string& sentence : kinematics::notAssembledNote(m, summary)) {
    err << (first ? "linkwright-cli: " : "  ") << sentence << "\n";
    first = false;
  }
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
    err << "linkwright-cli: note: " << kinematics::lockNote(m, step) << "\n";
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
        m, *spec, {}, kinematics::kSweepWindow, [&](const kinematics::SweepResult& part, std::size_t first) {
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
  for (const double q : summary.singularAngles) err << "linkwright-cli: note: " << kinematics::toggleNote(m, q) << "\n";
  noteLocks(m, summary.lockedBetween, err);
  undetermined.report(err);
  if (!summary.notAssembled.empty()) {
    reportUnassembled(summary, m, err);
    return ExitCode::NotAssemblable;
  }
  return ExitCode::Success;
}

}  // namespace linkwright::cli
