// `linkwright-cli arm`: the two-link arm of seed 004 (or any other) with its tip on a straight
// line at constant speed, one row per time sample. The request, its run and its rows are the
// core's (kinematics/design/arm_request.h, kinematics/io/arm_table.h), as Python's
// linkwright.arm has them; this command only turns the options into the request and prints.

#include "app/cli/commands.h"

#include "kinematics/design/arm_request.h"
#include "kinematics/io/arm_table.h"
#include "kinematics/io/safe_file.h"

#include <optional>
#include <ostream>
#include <vector>

namespace linkwright::cli {

namespace k = kinematics;

ExitCode runArm(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const k::ArmRequest request{inv.example, inv.arm,     inv.fromPoint, inv.toPoint,    inv.speed,
                              inv.elbow,   inv.samples, inv.stepTime,  inv.lengthUnit, k::FrontEnd::Cli};
  // The rows are written as the run hands them on, so 10⁷ of them take a few MB.
  std::optional<k::Result<k::ArmRun>> run;
  const auto writeRows = [&](std::ostream& to) -> std::optional<std::string> {
    std::optional<k::io::ArmTableWriter> writer;
    run = k::runArm(request, [&](const std::vector<k::ArmRow>& rows, std::size_t) {
      if (!writer) writer.emplace(to, request.lengthUnit, inv.tableFormat);
      writer->write(rows);
      return static_cast<bool>(to);  // a failed write stops the run; the writer says why
    });
    if (!*run && run->error().code != k::ErrorCode::Cancelled) return run->error().message;
    return std::nullopt;
  };
  const auto problem =
      inv.outputFile ? k::io::writeStreamSafely(*inv.outputFile, writeRows) : (writeRows(out), std::nullopt);
  if (run && !*run && run->error().code != k::ErrorCode::Cancelled) {
    err << "linkwright-cli: " << run->error().message << "\n";
    return ExitCode::BadInput;
  }
  if (problem) {
    err << "linkwright-cli: " << problem->message << "\n";
    return ExitCode::IoError;
  }
  // Cancelled by a standard output that failed: runCli says so, as for every command.
  if (!*run) return ExitCode::IoError;
  for (const std::string& note : k::armNotes(**run)) err << "linkwright-cli: " << note << "\n";
  return k::armLeavesWorkspace(**run) ? ExitCode::NotAssemblable : ExitCode::Success;
}

}  // namespace linkwright::cli
