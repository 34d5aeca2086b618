// `linkwright-cli arm`: the two-link arm of seed 004 (or any other) with its tip on a straight
// line at constant speed, one row per time sample. The request, its run and its rows are the
// core's (kinematics/design/arm_request.h, kinematics/io/arm_table.h), as Python's
// linkwright.arm has them; this command only turns the options into the request and prints.

#include "app/cli/commands.h"

#include "kinematics/design/arm_request.h"
#include "kinematics/io/arm_table.h"
#include "kinematics/io/safe_file.h"

#include <ostream>

namespace linkwright::cli {

namespace k = kinematics;

ExitCode runArm(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const k::ArmRequest request{inv.example, inv.arm,     inv.fromPoint, inv.toPoint,    inv.speed,
                              inv.elbow,   inv.samples, inv.stepTime,  inv.lengthUnit, k::FrontEnd::Cli};
  const auto run = k::runArm(request);
  if (!run) {
    err << "linkwright-cli: " << run.error().message << "\n";
    return ExitCode::BadInput;
  }
  const std::string text = inv.tableFormat ? k::io::armTable(*run) : k::io::armCsv(*run);
  if (inv.outputFile) {
    if (auto problem = k::io::writeFileSafely(*inv.outputFile, text)) {
      err << "linkwright-cli: " << problem->message << "\n";
      return ExitCode::IoError;
    }
  } else {
    out << text << std::flush;
  }
  for (const std::string& note : k::armNotes(*run)) err << "linkwright-cli: " << note << "\n";
  return k::armLeavesWorkspace(*run) ? ExitCode::NotAssemblable : ExitCode::Success;
}

}  // namespace linkwright::cli
