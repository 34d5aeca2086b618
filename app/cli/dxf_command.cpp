// `linkwright-cli dxf`: the links of a linkage as a DXF drawing at true size, at one input
// (kinematics/analysis/link_drawing.h for what is drawn, dxf_export.h for the file). The drawing and
// the file come from one core call, the one the designer's File ▸ Export ▸ DXF makes.

#include "app/cli/commands.h"

#include "kinematics/io/dxf_export.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/motion_law.h"
#include "kinematics/solve/pose_solver.h"

#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

// The input as the user reads it: "crank angle 30°" or "input 12.5 mm".
std::string inputText(const GridDefaults& d, double value) {
  if (d.input == k::InputKind::Angle) return "crank angle " + k::formatNumber(value) + "°";
  return "input " + k::formatNumber(value) + " " + d.lengthUnit;
}

// Where the design starts, as --at would give it: its time base's first instant, else its
// grid's first input.
double defaultInput(const GridDefaults& d) {
  if (!d.time) return d.fromDeg;
  const double q = k::motionAt(d.time->law, d.time->fromTime).position;
  return d.input == k::InputKind::Angle ? k::radToDeg(q) : q;
}

// A core refusal as the CLI's message: the drawing's fields are the options that set them.
std::string optionMessage(const k::Error& e) {
  if (e.field == "holeDiameter") return "--hole: " + e.message;
  if (e.field == "plateWidth") return "--width: " + e.message;
  return e.message;
}

void printSummary(std::ostream& out, const std::string& path, const k::LinkDrawing& drawing, const std::string& at) {
  const int units = k::io::dxfInsUnits(drawing.lengthUnit);
  out << "wrote " << path << ": the links at " << at << ", holes " << k::formatNumber(drawing.holeDiameter) << " "
      << drawing.lengthUnit << ", plates " << k::formatNumber(drawing.plateWidth) << " " << drawing.lengthUnit
      << " wide\n";
  out << "layers:";
  for (const k::DrawingLayer& layer : drawing.layers) out << " " << layer.name;
  out << "\n$INSUNITS " << units;
  if (units == 0) out << " (unitless: '" << drawing.lengthUnit << "' has no DXF unit code)";
  out << "\n";
}

}  // namespace

ExitCode runDxf(const Invocation& inv, std::ostream& out, std::ostream& err) {
  const auto resolved = resolveMechanism(inv);
  if (!resolved) {
    err << "linkwright-cli: " << resolved.error().message << "\n";
    return ExitCode::BadInput;
  }
  const k::Mechanism& m = resolved->mechanism;
  const GridDefaults& d = resolved->defaults;
  if (auto e = checkAtOption(inv, d)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  const double at = inv.atDeg.empty() ? defaultInput(d) : inv.atDeg.front();
  // Positions are all a drawing needs; without rates a toggle pose still draws.
  const auto pose = k::solvePose(m, {d.toInput(at), 0.0, 0.0}, k::SolveRequest{false, false});
  if (!pose) {
    err << "linkwright-cli: --at: " << resolved->source << " cannot be assembled at " << inputText(d, at) << ": "
        << pose.error().message << "\n";
    return ExitCode::NotAssemblable;
  }
  const k::DrawingOptions options{inv.holeDiameter, inv.plateWidth};
  const auto drawing = k::linkDrawing(m, *pose, options);
  if (!drawing) {
    err << "linkwright-cli: " << optionMessage(drawing.error()) << "\n";
    return ExitCode::BadInput;
  }
  if (auto e = k::io::writeDxf(*drawing, *inv.outputFile)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  printSummary(out, *inv.outputFile, *drawing, inputText(d, at));
  return ExitCode::Success;
}

}  // namespace linkwright::cli
