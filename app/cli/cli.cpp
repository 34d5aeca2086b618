#include "app/cli/cli.h"

#include "app/cli/arguments.h"
#include "app/cli/commands.h"
#include "app/cli/exit_codes.h"

#include <ostream>

namespace linkwright::cli {
namespace {

constexpr const char* kUsage = R"(Usage: linkwright-cli COMMAND [OPTIONS]

Planar linkage analysis (Linkwright's kinematics core, no GUI needed).

Commands:
  analyze    position, velocity and acceleration table of a linkage as CSV
  extremes   minimum and maximum of every column, refined between the samples
  classify   Grashof class, mobility, transmission angle, limit positions, time ratio
             (four-bars)
  examples   list the built-in examples
  --help [COMMAND], --version

)";

constexpr const char* kMechanismOptions = R"(Mechanism (one of):
  --fourbar FRAME,CRANK,COUPLER,ROCKER
                      link lengths, positive, in the length unit (default mm).
                      Crank pivot O2 at the origin, rocker pivot O4 at (FRAME, 0).
  --example NAME      a built-in example (see 'linkwright-cli examples'); analyze and
                      extremes also take the slider-crank and shaper examples
  --unit NAME         length unit label used in the output (default mm; letters only).
                      Lengths are taken and reported in this unit.
  --branch open|crossed
                      assembly branch: open has sin(rocker angle − coupler angle) > 0
                      (default open, or the example's)
)";

constexpr const char* kAnalyzeOptions = R"(Speed and range (analyze, extremes):
  --rpm R | --omega W crank speed in rev/min or rad/s, CCW positive
                      (default: the example's; 1 rad/s for --fourbar)
  --alpha A           crank angular acceleration, rad/s² (default 0). ω and α are the
                      crank's instantaneous state at every listed angle.
  --from DEG          first crank angle, degrees CCW from the frame line (default 0)
  --to DEG            last crank angle, degrees (default 360)
  --step DEG | --samples N
                      angle step in degrees (default: the example's; 1 for --fourbar),
                      or N evenly spaced angles from --from to --to inclusive
  --coupler-point U,V add point P fixed on the coupler: U along B→C, V 90° CCW from it
  --format csv|table  CSV (default) or an aligned table of the link columns, 4 decimals
  -o, --output FILE   write the output to FILE (atomically) instead of standard output

Output: RFC 4180 CSV, '.' decimal point, round-trip precision. Columns carry units:
  crank_angle_deg, <link>_angle_deg, <link>_omega_rad_s, <link>_alpha_rad_s2 for links
  crank, coupler (B→C), rocker (O4→C); transmission_angle_deg; <point>_x_<unit>,
  _y_, _vx_<unit>_s, _vy_, _ax_<unit>_s2, _ay_ for points B, C (and P). Link angles are
  continuous over the sweep. At a toggle position the ω and α cells are empty.
)";

constexpr const char* kClassifyOptions = R"(Classify options:
  --json              machine-readable output
)";

constexpr const char* kExitCodes = R"(Exit codes:
  0  success
  1  the output file could not be written
  2  bad usage or input: unknown option, malformed or invalid value (the message names it)
  3  the linkage cannot be assembled over the requested range (rows that assemble are
     still written; the message gives the ranges that do not and the range that does)

Example:
  linkwright-cli analyze --fourbar 60,25,70,45 --rpm 10 --step 30
)";

} // namespace

std::string helpText(const std::string& topic) {
  std::string text = kUsage;
  const bool sweeps = topic.empty() || topic == "analyze" || topic == "extremes";
  if (sweeps || topic == "classify") text += kMechanismOptions;
  if (sweeps) text += std::string("\n") + kAnalyzeOptions;
  if (topic.empty() || topic == "classify") text += std::string("\n") + kClassifyOptions;
  return text + "\n" + kExitCodes;
}

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const kinematics::Result<Invocation> parsed = parseArguments(args);
  if (!parsed) {
    err << "linkwright-cli: " << parsed.error().message << "\n";
    return toInt(ExitCode::BadInput);
  }
  const Invocation& inv = *parsed;
  switch (inv.command) {
  case Command::Help:
    if (!inv.helpTopic.empty() && inv.helpTopic != "analyze" && inv.helpTopic != "classify" && inv.helpTopic != "extremes" &&
        inv.helpTopic != "examples" && inv.helpTopic != "linkwright-cli") {
      err << "linkwright-cli: no help for '" << inv.helpTopic << "' (commands: analyze, classify, examples)\n";
      return toInt(ExitCode::BadInput);
    }
    out << helpText(inv.helpTopic == "linkwright-cli" || inv.helpTopic == "examples" ? "" : inv.helpTopic);
    return toInt(ExitCode::Success);
  case Command::Version:
    out << "linkwright-cli " << LINKWRIGHT_VERSION << "\n";
    return toInt(ExitCode::Success);
  case Command::Examples: return toInt(runExamples(out));
  case Command::Analyze: return toInt(runAnalyze(inv, out, err));
  case Command::Classify: return toInt(runClassify(inv, out, err));
  case Command::Extremes: return toInt(runExtremes(inv, out, err));
  }
  return toInt(ExitCode::BadInput);
}

} // namespace linkwright::cli
