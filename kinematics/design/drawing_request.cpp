#include "kinematics/design/drawing_request.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/motion_law.h"
#include "kinematics/solve/pose_solver.h"

namespace linkwright::kinematics {
namespace {

// The input as the user reads it: "crank angle 30°" or "input 12.5 mm".
std::string inputText(const SweepGrid& g, double value) {
  if (g.input == InputKind::Angle) return "crank angle " + formatNumber(value) + "°";
  return "input " + formatNumber(value) + " " + g.lengthUnit;
}

// Where the design starts: its time base's first instant, else its grid's first input.
double startInput(const SweepGrid& g) {
  if (!g.time) return g.fromDeg;
  const double q = motionAt(g.time->law, g.time->fromTime).position;
  return g.input == InputKind::Angle ? radToDeg(q) : q;
}

}  // namespace

Result<DrawingRun> runDrawing(const Mechanism& m, const SweepGrid& source, const std::string& name,
                              const DrawingRequest& r) {
  SweepGrid g = source;
  g.input = inputKind(m);
  g.lengthUnit = m.lengthUnit;
  const std::string atName = fieldName("at", r.frontEnd);
  if (r.at) {
    // On a time base the input is still what is drawn at, but --at is checked as an instant,
    // as for every command that takes it.
    const InputDomain domain = inputDomain(g.input);
    const bool angle = g.input == InputKind::Angle;
    const double max = g.time ? 1e6 : angle ? kMaxAngleDeg : domain.position;
    if (auto e = checkMagnitude(*r.at, atName, max, g.time ? "s" : angle ? "degrees" : domain.positionUnit)) return *e;
  }
  DrawingRun run;
  run.at = r.at.value_or(startInput(g));
  run.atText = inputText(g, run.at);
  // Positions are all a drawing needs; without rates a toggle pose still draws.
  const auto pose = solvePose(m, {g.toInput(run.at), 0.0, 0.0}, SolveRequest{false, false});
  if (!pose)
    return Error{ErrorCode::NotAssemblable, atName,
                 atName + ": " + name + " cannot be assembled at " + run.atText + ": " + pose.error().message};
  auto drawing = linkDrawing(m, *pose, r.options);
  if (!drawing) {
    Error e = drawing.error();
    const std::string key = e.field == "holeDiameter" ? "hole" : e.field == "plateWidth" ? "width" : "";
    if (!key.empty()) {
      e.field = fieldName(key, r.frontEnd);
      e.message = e.field + ": " + e.message;
    }
    return e;
  }
  run.drawing = std::move(*drawing);
  return run;
}

}  // namespace linkwright::kinematics
