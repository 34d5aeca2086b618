#include "kinematics/report/report_sections.h"

#include "kinematics/design/design_analysis.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics::report {
namespace {

using kinematics::ColumnQuantity;
using kinematics::formatFixed;
using kinematics::formatShort;

std::string deg(double radians) { return formatFixed(radToDeg(radians), 2) + "°"; }

std::string linkName(const Mechanism& m, std::size_t i) { return m.links[i].name; }
std::string pointName(const Mechanism& m, std::size_t i) { return m.points[i].name; }

bool isSliderPin(const Mechanism& m, std::size_t point) {
  return std::holds_alternative<RrpPoint>(m.points[point].definition);
}

// Whether the pin moves in y anywhere over the sweep: a slider on a level guide does not.
bool movesInY(const SweepResult& r, std::size_t point) {
  for (std::size_t j = 0; j < r.size(); ++j)
    if (r.assembled(j) && std::abs(r.position[point][j].y() - r.position[point][0].y()) > 1e-9) return true;
  return false;
}

std::string rangesText(const Mechanism& m, const std::vector<AngleRange>& ranges) {
  std::string text;
  for (const AngleRange& r : ranges)
    text += (text.empty() ? "" : ", ") + inputText(m, r.from, false) + " to " + inputText(m, r.to, false);
  return text;
}

void fourBarLines(const DesignAnalysis& a, const std::string& u, std::vector<InfoLine>& lines) {
  const GrashofReport& g = *a.grashof;
  lines.push_back({"Grashof class", std::string(toString(g.category)) +
                                        " (shortest link: " + std::string(toString(g.shortest)) +
                                        ", longest: " + std::string(toString(g.longest)) + ")"});
  lines.push_back({"S + L, P + Q", formatShort(g.sPlusL) + " " + u + ", " + formatShort(g.pPlusQ) + " " + u});
  if (a.transmission)
    lines.push_back({"Transmission angle",
                     "min " + deg(a.transmission->minimum) + " at crank " + deg(a.transmission->minimumAtCrank) +
                         ", max " + deg(a.transmission->maximum) + " at crank " + deg(a.transmission->maximumAtCrank)});
  for (const LimitPosition& p : a.limits.positions)
    lines.push_back({"Rocker limit", std::string(p.extended ? "extended" : "folded") + ": crank " + deg(p.crankAngle) +
                                         ", rocker " + deg(p.rockerAngle)});
  if (a.limits.rockerSwing) lines.push_back({"Rocker swing", deg(*a.limits.rockerSwing)});
  if (a.limits.timeRatio)
    lines.push_back({"Time ratio", formatFixed(*a.limits.timeRatio, 4) + " (slow stroke " +
                                       deg(*a.limits.slowStrokeCrankArc) + ", quick stroke " +
                                       deg(*a.limits.quickStrokeCrankArc) + ")"});
}

}  // namespace

TableColumn columnHeading(const Mechanism& m, const kinematics::SweepColumn& c, const ReportUnits& units) {
  const std::string& u = m.lengthUnit;
  const std::string angular = units.rates == RateUnit::Degrees ? "deg" : "rad";
  const std::string angle = units.angles == AngleUnit::Radians ? "rad" : "deg";
  // The input angle stays in degrees, as the grid is given (unitScale leaves it).
  const std::string unit =
      kinematics::columnUnit(c.quantity, u, c.quantity == ColumnQuantity::InputAngle ? "deg" : angle, angular);
  switch (c.quantity) {
  case ColumnQuantity::Time: return {"time", unit};
  case ColumnQuantity::InputAngle:
  case ColumnQuantity::InputLength: return {inputName(m), unit};
  case ColumnQuantity::LinkAngle: return {linkName(m, c.index) + " θ", unit};
  case ColumnQuantity::LinkOmega: return {linkName(m, c.index) + " ω", unit};
  case ColumnQuantity::LinkAlpha: return {linkName(m, c.index) + " α", unit};
  case ColumnQuantity::TransmissionAngle: return {"μ at " + pointName(m, c.index), unit};
  case ColumnQuantity::PointX: return {pointName(m, c.index) + " x", unit};
  case ColumnQuantity::PointY: return {pointName(m, c.index) + " y", unit};
  case ColumnQuantity::PointVx: return {pointName(m, c.index) + " vx", unit};
  case ColumnQuantity::PointVy: return {pointName(m, c.index) + " vy", unit};
  case ColumnQuantity::PointAx: return {pointName(m, c.index) + " ax", unit};
  case ColumnQuantity::PointAy: return {pointName(m, c.index) + " ay", unit};
  }
  return {c.name, ""};
}

double unitScale(const kinematics::SweepColumn& c, const ReportUnits& units) {
  const bool linkRate = c.quantity == ColumnQuantity::LinkOmega || c.quantity == ColumnQuantity::LinkAlpha;
  const bool angle = c.quantity == ColumnQuantity::LinkAngle || c.quantity == ColumnQuantity::TransmissionAngle;
  if (linkRate && units.rates == RateUnit::Degrees) return radToDeg(1.0);
  if (angle && units.angles == AngleUnit::Radians) return degToRad(1.0);
  return 1.0;
}

std::string columnName(const kinematics::SweepColumn& c, const ReportUnits& units) {
  if (unitScale(c, units) == 1.0) return c.name;
  // analyze's names end in _rad_s or _rad_s2 for a link's ω and α, in _deg for an angle.
  if (const std::size_t at = c.name.rfind("_rad_s"); at != std::string::npos)
    return c.name.substr(0, at) + "_deg_s" + c.name.substr(at + 6);
  if (c.name.ends_with("_deg")) return c.name.substr(0, c.name.size() - 4) + "_rad";
  return c.name;
}

std::vector<kinematics::SweepColumn> reportColumns(const Mechanism& m, const SweepResult& r) {
  std::vector<kinematics::SweepColumn> columns;
  const bool timeBase = !r.time.empty();
  for (kinematics::SweepColumn& c : kinematics::sweepColumns(m, r.request, timeBase)) {
    const bool linkRate = c.quantity == ColumnQuantity::LinkOmega || c.quantity == ColumnQuantity::LinkAlpha;
    // On a grid the crank's ω and α are the grid's constants; on a time base the law's.
    if (linkRate && !timeBase && kinematics::isDrivenCrankLink(m, LinkId{c.index})) continue;
    bool keep = c.quantity <= ColumnQuantity::TransmissionAngle;
    if (c.quantity > ColumnQuantity::TransmissionAngle && isSliderPin(m, c.index)) {
      const bool inY = c.quantity == ColumnQuantity::PointY || c.quantity == ColumnQuantity::PointVy ||
                       c.quantity == ColumnQuantity::PointAy;
      keep = !inY || movesInY(r, c.index);
    }
    if (keep) columns.push_back(std::move(c));
  }
  return columns;
}

std::vector<PlotKind> plotKinds(const Mechanism& m, const ReportUnits& units) {
  const std::string angular = units.rates == RateUnit::Degrees ? "deg" : "rad";
  const std::string angle = units.angles == AngleUnit::Radians ? "rad" : "deg";
  const auto unit = [&](ColumnQuantity q) { return kinematics::columnUnit(q, m.lengthUnit, angle, angular); };
  return {{"Link angles θ", unit(ColumnQuantity::LinkAngle), {ColumnQuantity::LinkAngle}},
          {"Angular velocities ω", unit(ColumnQuantity::LinkOmega), {ColumnQuantity::LinkOmega}},
          {"Angular accelerations α", unit(ColumnQuantity::LinkAlpha), {ColumnQuantity::LinkAlpha}},
          {"Transmission angle μ", unit(ColumnQuantity::TransmissionAngle), {ColumnQuantity::TransmissionAngle}},
          {"Slider position", unit(ColumnQuantity::PointX), {ColumnQuantity::PointX, ColumnQuantity::PointY}},
          {"Slider velocity", unit(ColumnQuantity::PointVx), {ColumnQuantity::PointVx, ColumnQuantity::PointVy}},
          {"Slider acceleration", unit(ColumnQuantity::PointAx), {ColumnQuantity::PointAx, ColumnQuantity::PointAy}}};
}

std::string inputText(const Mechanism& m, double input, bool named) {
  const std::string unit = inputUnit(m);
  const std::string value = formatShort(inputDisplayValue(m, input)) + (unit == "°" ? unit : " " + unit);
  return named ? inputName(m) + " " + value : value;
}

std::string gridCaption(const Mechanism& m, const SweepSpec& spec, const std::string& sampling, RateUnit rates) {
  std::string name = inputName(m);
  if (!name.empty()) name[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[0])));
  const bool crank = inputKind(m) == InputKind::Angle;
  const bool degrees = crank && rates == RateUnit::Degrees;
  const std::string rate = !crank ? m.lengthUnit + "/s" : degrees ? "deg/s" : "rad/s";
  const double scale = degrees ? radToDeg(1.0) : 1.0;
  return name + " " + inputText(m, spec.fromAngle, false) + " to " + inputText(m, spec.toAngle, false) + ", " +
         sampling + "; " + (crank ? "crank " : "driver ") + formatShort(spec.omega * scale) + " " + rate + ", " +
         formatShort(spec.alpha * scale) + " " + rate + "²";
}

std::string timeCaption(const Mechanism& m, const SweepSpec& spec, const std::string& sampling) {
  const bool crank = inputKind(m) == InputKind::Angle;
  return "Time " + formatShort(spec.time->fromTime) + " s to " + formatShort(spec.time->toTime) + " s, " + sampling +
         "; the " + (crank ? "crank" : "driver") + " follows its motion law";
}

std::vector<InfoLine> analysisLines(const Mechanism& m, const SweepResult& gridSweep) {
  const DesignAnalysis a = analyseDesign(m, gridSweep);
  const MobilityReport& mob = a.mobility;
  std::vector<InfoLine> lines;
  if (a.grashof) fourBarLines(a, m.lengthUnit, lines);
  lines.push_back({"Mobility (Gruebler)", "M = 3(" + std::to_string(mob.links) + " − 1) − 2·" +
                                              std::to_string(mob.fullJoints) + " − " + std::to_string(mob.halfJoints) +
                                              " = " + std::to_string(mob.mobility)});
  const InputRange& range = a.inputRange;
  std::string where = range.fullRotation     ? "all " + inputName(m) + "s (the crank turns fully)"
                      : range.ranges.empty() ? "none: the loop never closes"
                                             : rangesText(m, range.ranges);
  lines.push_back({"Assembles at", where});
  if (const auto& q = a.quickReturn) {
    lines.push_back({"Limit crank angles", deg(q->firstLimitCrankAngle) + " and " + deg(q->secondLimitCrankAngle)});
    lines.push_back({"Time ratio", formatFixed(q->timeRatio, 4) + " (slow stroke " + deg(q->slowStrokeCrankArc) +
                                       ", quick stroke " + deg(q->quickStrokeCrankArc) + ")"});
    lines.push_back({"Ram stroke", formatShort(q->stroke, 8) + " " + m.lengthUnit});
  }
  return lines;
}

Result<ReportDrawing> reportDrawing(const Mechanism& m, double at) {
  const auto pose = solvePose(m, {at, 0.0, 0.0}, SolveRequest{false, false});
  if (!pose)
    return Error{ErrorCode::NotAssemblable, "--at",
                 "the linkage cannot be assembled at " + inputText(m, at) + ": " + pose.error().message};
  auto parts = kinematics::linkDrawing(m, *pose, {});
  if (!parts) return parts.error();
  ReportDrawing drawing{std::move(*parts), {}, {}, {}, "at " + inputText(m, at)};
  const std::string& u = m.lengthUnit;
  for (const Link& link : m.links) {
    const Eigen::Vector2d a = pose->position[link.first.index];
    const Eigen::Vector2d b = pose->position[link.second.index];
    drawing.dimensions.push_back({a, b, link.name + " " + formatShort((b - a).norm()) + " " + u});
  }
  std::vector<Eigen::Vector2d> ground;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    drawing.pointLabels.emplace_back(pose->position[i], m.points[i].name);
    if (std::holds_alternative<GroundPoint>(m.points[i].definition)) ground.push_back(pose->position[i]);
  }
  // The frame is a link too: between two ground pivots its length is a dimension.
  if (ground.size() == 2)
    drawing.dimensions.push_back(
        {ground[0], ground[1], "frame " + formatShort((ground[1] - ground[0]).norm()) + " " + u, true});
  drawing.groundPivots = std::move(ground);
  return drawing;
}

std::vector<std::string> sweepNotes(const Mechanism& m, const SweepResult& r) {
  std::vector<std::string> notes;
  for (const double q : r.singularAngles)
    notes.push_back("Toggle position at " + inputText(m, q) + ": ω and α are undefined there.");
  if (!r.notAssembled.empty())
    notes.push_back("The linkage cannot be assembled at " + rangesText(m, r.notAssembled) +
                    "; those rows are left out.");
  for (const AngleRange& step : r.lockedBetween)
    notes.push_back("The linkage locks between " + inputText(m, step.from) + " and " + inputText(m, step.to) + ".");
  return notes;
}

}  // namespace linkwright::kinematics::report
