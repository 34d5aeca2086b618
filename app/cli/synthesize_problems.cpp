// Runs the core's synthesis for each problem and turns what it returns into report rows: the
// options become the core's target (degrees to radians here, at the edge), and a core error's
// field ("timeRatio", "circlePoints.a") becomes the option the user typed.

#include "app/cli/synthesize_report.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/synthesis/function_generation.h"
#include "kinematics/synthesis/motion_generation.h"
#include "kinematics/synthesis/named_function.h"
#include "kinematics/synthesis/path_generation.h"
#include "kinematics/synthesis/stroke_shaper.h"
#include "kinematics/synthesis/stroke_slider_crank.h"
#include "kinematics/synthesis/swing_crank_rocker.h"

#include <algorithm>
#include <utility>

namespace linkwright::cli {
namespace {

namespace k = kinematics;
using Detail = SynthesisDetail;
using Kind = SynthesisDetail::Kind;

// The core's field (or its prefix before '[' or '.') to the option that set it.
using FieldMap = std::vector<std::pair<std::string, std::string>>;

k::Error optionError(const k::Error& e, const FieldMap& fields, const std::string& problem) {
  for (const auto& [field, option] : fields)
    if (e.field == field || e.field.rfind(field + "[", 0) == 0 || e.field.rfind(field + ".", 0) == 0)
      return k::Error{e.code, option, option + ": " + e.message};
  return k::Error{e.code, "synthesize " + problem, "synthesize " + problem + ": " + e.message};
}

std::string deg(double degrees) { return k::formatShort(degrees) + "°"; }
std::string len(double value, const std::string& unit) { return k::formatShort(value) + " " + unit; }
std::string branchName(k::Branch b) { return b == k::Branch::Open ? "open" : "crossed"; }

k::DefectBounds boundsOf(const SynthesisRequest& r) { return targetsOf(r).bounds; }

std::vector<std::pair<std::string, double>> fourBarDimensions(const k::FourBarLengths& l) {
  return {{"frame", l.frame}, {"crank", l.crank}, {"coupler", l.coupler}, {"rocker", l.rocker}};
}

SynthesisReport reportFor(const SynthesisRequest& r) {
  SynthesisReport report;
  report.problem = r.problem;
  report.lengthUnit = r.lengthUnit;
  report.minTransmissionDeg = r.minTransmissionDeg;
  report.maxLink = r.maxLink;
  report.maxLinkRatio = r.maxLinkRatio;
  return report;
}

CandidateRow swingRow(const k::CrankRockerCandidate& c) {
  CandidateRow row{c.candidate, fourBarDimensions(c.lengths), c.parameter, {}};
  row.details = {
      {"branch", "branch", Kind::Text, {}, branchName(c.branch)},
      {"extended_limit_deg",
       "extended limit (crank, rocker)",
       Kind::AngleDeg,
       {k::radToDeg(c.extendedCrankAngle), k::radToDeg(c.extendedRockerAngle)},
       ""},
      {"folded_limit_deg",
       "folded limit (crank, rocker)",
       Kind::AngleDeg,
       {k::radToDeg(c.foldedCrankAngle), k::radToDeg(c.foldedRockerAngle)},
       ""},
  };
  return row;
}

k::Result<SynthesisReport> solveSwing(const SynthesisRequest& r) {
  const bool rocker = r.rocker.has_value();
  const k::SwingTarget target = targetsOf(r).swing;
  const auto s = k::synthesiseCrankRocker(target, static_cast<std::size_t>(r.count), boundsOf(r));
  if (!s)
    return optionError(s.error(),
                       {{"swing", "--swing"},
                        {"timeRatio", "--time-ratio"},
                        {"length", rocker ? "--rocker" : "--frame"},
                        {"count", "--count"}},
                       "swing");
  SynthesisReport report = reportFor(r);
  report.summary = "crank-rocker: rocker swing " + deg(*r.swingDeg) + ", time ratio " + k::formatShort(*r.timeRatio) +
                   ", " + (rocker ? "rocker " : "frame ") + len(target.length, r.lengthUnit);
  // The family in order of its parameter, the best in its place among them.
  for (const k::CrankRockerCandidate& c : s->family) report.rows.push_back(swingRow(c));
  const auto at = std::find_if(report.rows.begin(), report.rows.end(),
                               [&](const CandidateRow& row) { return *row.parameter > s->best.parameter; });
  report.best = static_cast<std::size_t>(at - report.rows.begin());
  report.rows.insert(at, swingRow(s->best));
  report.bestRule =
      "the largest worst transmission angle with longest / shortest link <= " + k::formatShort(r.maxLinkRatio) +
      " (or, if none meets that, of all)";
  return report;
}

k::Result<SynthesisReport> solveSlider(const SynthesisRequest& r) {
  const bool rod = r.rod.has_value();
  const k::StrokeTarget target = targetsOf(r).slider;
  const auto s = k::synthesiseSliderCrank(target, boundsOf(r));
  if (!s)
    return optionError(
        s.error(), {{"stroke", "--stroke"}, {"timeRatio", "--time-ratio"}, {"rod", "--rod"}, {"offset", "--offset"}},
        "slider");
  SynthesisReport report = reportFor(r);
  report.summary = "offset slider-crank: stroke " + len(*r.stroke, r.lengthUnit) + ", time ratio " +
                   k::formatShort(*r.timeRatio) + ", " + (rod ? "rod " : "offset ") + len(target.value, r.lengthUnit);
  const k::SliderCrankGeometry& g = s->geometry;
  CandidateRow row{s->candidate, {{"crank", g.crank}, {"rod", g.rod}, {"offset", g.offset}}, std::nullopt, {}};
  row.details = {
      {"stroke_ends", "stroke from, to (x along the guide)", Kind::Length, {s->nearEnd, s->farEnd}, ""},
      {"extended_crank_angle_deg",
       "crank angle at the far end",
       Kind::AngleDeg,
       {k::radToDeg(s->extendedCrankAngle)},
       ""},
      {"folded_crank_angle_deg", "crank angle at the near end", Kind::AngleDeg, {k::radToDeg(s->foldedCrankAngle)}, ""},
  };
  report.rows.push_back(std::move(row));
  report.bestRule = "the only slider-crank for this stroke, time ratio and " + std::string(rod ? "rod" : "offset");
  return report;
}

k::Result<SynthesisReport> solveShaper(const SynthesisRequest& r) {
  const k::ShaperTarget target = targetsOf(r).shaper;
  const auto s = k::synthesiseShaper(target, boundsOf(r));
  if (!s)
    return optionError(s.error(),
                       {{"stroke", "--stroke"},
                        {"timeRatio", "--time-ratio"},
                        {"crank", "--crank"},
                        {"link", "--link"},
                        {"guideHeight", "--guide-height"}},
                       "shaper");
  SynthesisReport report = reportFor(r);
  report.summary = "crank-shaper: ram stroke " + len(*r.stroke, r.lengthUnit) + ", time ratio " +
                   k::formatShort(*r.timeRatio) + ", crank " + len(*r.crank, r.lengthUnit) + ", link " +
                   len(*r.link, r.lengthUnit);
  const k::ShaperGeometry& g = s->geometry;
  CandidateRow row{s->candidate,
                   {{"crank", g.crank}, {"frame", g.rockerPivot.norm()}, {"lever", g.rocker}, {"link", g.link}},
                   std::nullopt,
                   {}};
  row.details = {
      {"rocker_pivot", "slotted lever pivot O4 (x, y)", Kind::Length, {g.rockerPivot.x(), g.rockerPivot.y()}, ""},
      {"guide_height", "ram guide height (y)", Kind::Length, {g.guideHeight}, ""},
  };
  report.rows.push_back(std::move(row));
  report.bestRule = "the only crank-shaper for this stroke, time ratio, crank and link";
  return report;
}

k::Result<SynthesisReport> solveFunction(const SynthesisRequest& r) {
  const auto s = k::synthesiseFunction(targetsOf(r).function, r.lengthUnit, boundsOf(r));
  if (!s)
    return optionError(s.error(),
                       {{"function", "--function"},
                        {"x0", "--x0"},
                        {"x1", "--x1"},
                        {"inputStart", "--input-start"},
                        {"inputSpan", "--input-span"},
                        {"outputStart", "--output-start"},
                        {"outputSpan", "--output-span"},
                        {"frame", "--frame"},
                        {"count", "--points"},
                        {"points", r.at.empty() ? "--points" : "--at"}},
                       "function");
  SynthesisReport report = reportFor(r);
  report.summary = "function generator: y = " + r.function + "(x), x from " + k::formatShort(*r.x0) + " to " +
                   k::formatShort(*r.x1) + "; crank from " + deg(*r.inputStartDeg) + " through " +
                   deg(*r.inputSpanDeg) + ", rocker from " + deg(*r.outputStartDeg) + " through " +
                   deg(*r.outputSpanDeg) + "; " + std::to_string(s->points.size()) +
                   (r.at.empty() ? " Chebyshev" : "") + " precision points" +
                   (s->points.size() > 3 ? " (least squares)" : "");
  report.errorName = "worst output error";
  report.errorUnit = "deg";
  report.errorFactor = k::radToDeg(1.0);
  CandidateRow row{s->candidate, fourBarDimensions(s->linkage.lengths), std::nullopt, {}};
  std::vector<double> crank, output;
  for (const k::AnglePair& p : s->precisionAngles) {
    crank.push_back(k::radToDeg(p.input));
    output.push_back(k::radToDeg(p.output));
  }
  row.details = {
      {"precision_x", "precision points x", Kind::Plain, s->points, ""},
      {"precision_crank_angle_deg", "crank angles there", Kind::AngleDeg, crank, ""},
      {"precision_output_angle_deg", "output angles there", Kind::AngleDeg, output, ""},
      {"branch", "branch", Kind::Text, {}, branchName(s->branch)},
      {"crank_phase_deg", "crank phase (180°: reversed)", Kind::AngleDeg, {s->linkage.crankReversed ? 180.0 : 0.0}, ""},
      {"output_offset_deg", "output offset (rocker − output)", Kind::AngleDeg, {k::radToDeg(s->outputOffset)}, ""},
      {"worst_error_at_x", "worst error at x", Kind::Plain, {s->error.maxAt}, ""},
      {"worst_error_y", "worst error in y", Kind::Plain, {s->error.maxAbsY}, ""},
      {"not_assembled_samples",
       "samples not assembled",
       Kind::Plain,
       {static_cast<double>(s->error.notAssembled.size())},
       ""},
  };
  report.rows.push_back(std::move(row));
  report.bestRule = "Freudenstein's solution through the precision points";
  return report;
}

k::Result<SynthesisReport> solveMotion(const SynthesisRequest& r) {
  const k::MotionTargets m = targetsOf(r).motion;
  const std::vector<k::CouplerPose>& poses = m.poses;
  const k::MotionOptions options{m.needsFullRotation, r.lengthUnit};
  const auto s = poses.size() == 3
                     ? k::synthesiseMotion3(poses, m.circlePoints, boundsOf(r), options)
                     : k::synthesiseMotion2(poses, m.circlePoints, m.centreA, m.centreB, boundsOf(r), options);
  if (!s) {
    // The core names the circle points and centres by member; the user typed them in order.
    k::Error e = s.error();
    for (const auto& [member, typed] : {std::pair{"circlePoints.a", "the first --circle-point"},
                                        {"circlePoints.b", "the second --circle-point"},
                                        {"centreA", "the first --centre"},
                                        {"centreB", "the second --centre"}})
      for (std::size_t at; (at = e.message.find(member)) != std::string::npos;)
        e.message.replace(at, std::string(member).size(), typed);
    return optionError(e,
                       {{"poses", "--pose"},
                        {"circlePoints.a", "--circle-point"},
                        {"circlePoints.b", "--circle-point"},
                        {"centreA", "--centre"},
                        {"centreB", "--centre"}},
                       "motion");
  }
  SynthesisReport report = reportFor(r);
  report.summary = "motion generator: coupler point and angle through " + std::to_string(poses.size()) + " poses" +
                   (poses.size() == 3 ? " (Burmester)" : "");
  CandidateRow row{s->candidate, fourBarDimensions(s->lengths), std::nullopt, {}};
  std::vector<double> crank;
  for (const double a : s->crankAngles) crank.push_back(k::radToDeg(a));
  row.details = {
      {"crank_pivot", "crank pivot O2 (x, y)", Kind::Length, {s->o2.x(), s->o2.y()}, ""},
      {"rocker_pivot", "rocker pivot O4 (x, y)", Kind::Length, {s->o4.x(), s->o4.y()}, ""},
      {"pose_crank_angle_deg", "crank angle at each pose (from +x)", Kind::AngleDeg, crank, ""},
      {"branch", "branch at pose 1", Kind::Text, {}, branchName(s->branch)},
  };
  report.rows.push_back(std::move(row));
  report.bestRule = "the four-bar of the given circle points";
  return report;
}

CandidateRow pathRow(const k::PathCandidate& c) {
  CandidateRow row{c.candidate, fourBarDimensions(c.lengths), std::nullopt, {}};
  std::vector<double> crank;
  for (const double a : c.crankAngles) crank.push_back(k::radToDeg(a));
  row.details = {
      {"crank_pivot", "crank pivot O2 (x, y)", Kind::Length, {c.o2.x(), c.o2.y()}, ""},
      {"rocker_pivot", "rocker pivot O4 (x, y)", Kind::Length, {c.o4.x(), c.o4.y()}, ""},
      {"coupler_point",
       "coupler point (along, across B->C)",
       Kind::Length,
       {c.couplerPoint.along, c.couplerPoint.across},
       ""},
      {"target_crank_angle_deg", "crank angle at each target (from +x)", Kind::AngleDeg, crank, ""},
      {"target_distances", "distance to each target", Kind::Length, c.distances, ""},
      {"branch", "branch", Kind::Text, {}, branchName(c.branch)},
      {"found_by_start", "found by start", Kind::Plain, {static_cast<double>(c.start + 1)}, ""},
      {"seconds_to_find", "found after (s)", Kind::Plain, {c.secondsToFind}, ""},
  };
  return row;
}

k::Result<SynthesisReport> solvePath(const SynthesisRequest& r, const k::PathProgress& progress) {
  const k::SynthesisTargets t = targetsOf(r);
  const k::PathTarget& target = t.path;
  k::PathOptions options;
  options.starts = t.pathSearch.starts;
  options.seed = t.pathSearch.seed;
  const auto s = k::synthesisePath(target, options, boundsOf(r), nullptr, progress);
  if (!s)
    return optionError(s.error(), {{"points", "--target"}, {"timing", "--timing"}, {"starts", "--starts"}}, "path");
  if (s->candidates.empty())
    return k::Error{k::ErrorCode::NotAssemblable, "--target",
                    "--target: no start of " + std::to_string(s->startsRun) +
                        " gave a four-bar assembled at every target; try more --starts or another --seed"};
  SynthesisReport report = reportFor(r);
  report.summary = "path generator: coupler point through " + std::to_string(r.targets.size()) + " targets" +
                   (r.timingDeg.empty() ? "" : " at the given crank angles") + "; " + std::to_string(s->startsRun) +
                   " Levenberg-Marquardt starts (seed " + std::to_string(options.seed) + ")";
  report.errorName = "worst distance to a target";
  report.errorUnit = r.lengthUnit;
  for (const k::PathCandidate& c : s->candidates) report.rows.push_back(pathRow(c));
  report.best = 0;
  report.bestRule = "the smallest worst distance (candidates are distinct local minima, best first)";
  return report;
}

}  // namespace

k::SynthesisTargets targetsOf(const SynthesisRequest& r) {
  k::SynthesisTargets t;
  t.problem = r.problem;
  const std::string& u = r.lengthUnit;
  const double q = r.timeRatio.value_or(1.0);
  switch (r.problem) {
  case SynthesisProblem::Swing:
    t.swing = {k::degToRad(r.swingDeg.value_or(0.0)), q, r.rocker ? *r.rocker : r.frame.value_or(0.0),
               r.rocker ? k::SwingScale::Rocker : k::SwingScale::Frame, u};
    break;
  case SynthesisProblem::Slider:
    t.slider = {r.stroke.value_or(0.0), q, r.rod ? k::SliderChoice::Rod : k::SliderChoice::Offset,
                r.rod ? *r.rod : r.offset.value_or(0.0), u};
    break;
  case SynthesisProblem::Shaper:
    t.shaper = {r.stroke.value_or(0.0), q, r.crank.value_or(0.0), r.link.value_or(0.0), r.guideHeight, u};
    break;
  case SynthesisProblem::Function:
    t.function = {r.function,
                  r.x0.value_or(0.0),
                  r.x1.value_or(0.0),
                  k::degToRad(r.inputStartDeg.value_or(0.0)),
                  k::degToRad(r.inputSpanDeg.value_or(0.0)),
                  k::degToRad(r.outputStartDeg.value_or(0.0)),
                  k::degToRad(r.outputSpanDeg.value_or(0.0)),
                  r.frame.value_or(100.0),
                  r.at,
                  static_cast<std::size_t>(r.points.value_or(3))};
    break;
  case SynthesisProblem::Motion:
    for (const PoseOption& p : r.poses) t.motion.poses.push_back({p.point, k::degToRad(p.angleDeg)});
    if (r.circlePoints.size() == 2) t.motion.circlePoints = {r.circlePoints[0], r.circlePoints[1]};
    if (r.centres.size() == 2) {
      t.motion.centreA = r.centres[0];
      t.motion.centreB = r.centres[1];
    }
    t.motion.needsFullRotation = r.fullTurn;
    break;
  case SynthesisProblem::Path:
    t.path.points = r.targets;
    for (const double a : r.timingDeg) t.path.timing.push_back(k::degToRad(a));
    t.path.timingReference = r.timingFromFrame ? k::TimingReference::Frame : k::TimingReference::Start;
    t.path.needsFullRotation = r.fullTurn;
    t.path.lengthUnit = u;
    if (r.starts) t.pathSearch.starts = static_cast<int>(*r.starts);
    if (r.seed) t.pathSearch.seed = static_cast<std::uint32_t>(*r.seed);
    break;
  }
  t.bounds.minTransmission = k::degToRad(r.minTransmissionDeg);
  t.bounds.maxLinkLength = r.maxLink;
  t.bounds.maxLinkRatio = r.maxLinkRatio;
  return t;
}

k::Result<SynthesisReport> solveSynthesis(const SynthesisRequest& r, const k::PathProgress& progress) {
  switch (r.problem) {
  case SynthesisProblem::Swing: return solveSwing(r);
  case SynthesisProblem::Slider: return solveSlider(r);
  case SynthesisProblem::Shaper: return solveShaper(r);
  case SynthesisProblem::Function: return solveFunction(r);
  case SynthesisProblem::Motion: return solveMotion(r);
  case SynthesisProblem::Path: return solvePath(r, progress);
  }
  return k::Error{k::ErrorCode::InvalidValue, "PROBLEM", "unknown synthesis problem"};
}

}  // namespace linkwright::cli
