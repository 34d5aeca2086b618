// `linkwright-cli dxf`: the links of a linkage as a DXF drawing at true size, at one input
// (kinematics/analysis/link_drawing.h for what is drawn, dxf_export.h for the file). The drawing and
// the file come from one core call, the one the designer's File ▸ Export ▸ DXF makes.

#include "app/cli/commands.h"

#include "kinematics/design/drawing_request.h"
#include "kinematics/io/dxf_export.h"
#include "kinematics/model/number_text.h"

#include <ostream>

namespace linkwright::cli {
namespace {

namespace k = kinematics;

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
  if (auto e = checkAtOption(inv, resolved->defaults)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::BadInput;
  }
  k::DrawingRequest request;
  if (!inv.atDeg.empty()) request.at = inv.atDeg.front();
  request.options = {inv.holeDiameter, inv.plateWidth};
  const auto run = k::runDrawing(resolved->mechanism, resolved->defaults, resolved->source, request);
  if (!run) {
    err << "linkwright-cli: " << run.error().message << "\n";
    return run.error().code == k::ErrorCode::NotAssemblable ? ExitCode::NotAssemblable : ExitCode::BadInput;
  }
  const k::LinkDrawing* drawing = &run->drawing;
  if (auto e = k::io::writeDxf(*drawing, *inv.outputFile)) {
    err << "linkwright-cli: " << e->message << "\n";
    return ExitCode::IoError;
  }
  printSummary(out, *inv.outputFile, *drawing, run->atText);
  return ExitCode::Success;
}

}  // namespace linkwright::cli
