#include "ui/synthesis/synthesis_solve.h"

#include "ui/number_text.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <QCoreApplication>

#include <type_traits>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("SynthesisSolve", text); }

QString degreesText(double radians) { return numberText(k::radToDeg(radians), 'f', 1) + QStringLiteral("°"); }

// Where `point` of the candidate's linkage is at each input, by the pose solver; inputs at
// which it does not assemble mark nothing.
std::vector<Eigen::Vector2d> pointAt(const k::Design& design, k::PointId point, const std::vector<double>& inputs) {
  std::vector<Eigen::Vector2d> out;
  for (const double input : inputs) {
    const auto pose = k::solvePose(design.mechanism, {input, 0.0, 0.0}, {false, false});
    if (pose && point.index < pose->position.size()) out.push_back(pose->position[point.index]);
  }
  return out;
}

SynthesisRow crankRockerRow(const k::CrankRockerCandidate& c, const QString& label) {
  SynthesisRow row{c.candidate, label, c.foldedCrankAngle, {}};
  row.targets.points = pointAt(c.candidate.design, k::fourbar::kC, {c.foldedCrankAngle, c.extendedCrankAngle});
  return row;
}

k::Result<SynthesisOutcome> solve(const SwingRequest& r, const k::DefectBounds& bounds) {
  const auto s = k::synthesiseCrankRocker(r.target, r.count, bounds);
  if (!s) return s.error();
  SynthesisOutcome out;
  out.errorUnit = QString::fromStdString(r.target.lengthUnit);
  out.exact = true;
  out.rows.push_back(crankRockerRow(s->best, tr("best")));
  for (std::size_t i = 0; i < s->family.size(); ++i)
    out.rows.push_back(crankRockerRow(s->family[i], QString::number(i + 1)));
  out.summary = tr("%1 crank-rockers of the family; the best keeps the transmission angle above %2")
                    .arg(s->family.size())
                    .arg(degreesText(s->best.candidate.minTransmission));
  return out;
}

k::Result<SynthesisOutcome> solve(const k::StrokeTarget& r, const k::DefectBounds& bounds) {
  const auto s = k::synthesiseSliderCrank(r, bounds);
  if (!s) return s.error();
  SynthesisOutcome out;
  out.errorUnit = QString::fromStdString(r.lengthUnit);
  out.exact = true;
  SynthesisRow row{s->candidate, QStringLiteral("1"), s->foldedCrankAngle, {}};
  row.targets.points = pointAt(s->candidate.design, k::slidercrank::kC, {s->foldedCrankAngle, s->extendedCrankAngle});
  out.rows.push_back(row);
  out.summary = tr("Crank %1, rod %2, offset %3 %4")
                    .arg(numberText(s->geometry.crank), numberText(s->geometry.rod), numberText(s->geometry.offset),
                         out.errorUnit);
  return out;
}

k::Result<SynthesisOutcome> solve(const k::ShaperTarget& r, const k::DefectBounds& bounds) {
  const auto s = k::synthesiseShaper(r, bounds);
  if (!s) return s.error();
  SynthesisOutcome out;
  out.errorUnit = QString::fromStdString(r.lengthUnit);
  out.exact = true;
  const k::Design& d = s->candidate.design;
  out.rows.push_back({s->candidate, QStringLiteral("1"), k::inputFromDisplay(d.mechanism, d.fromDeg), {}});
  out.summary = tr("Crank %1, pivots %2 apart, lever %3 %4")
                    .arg(numberText(s->geometry.crank), numberText(s->geometry.rockerPivot.norm()),
                         numberText(s->geometry.rocker), out.errorUnit);
  return out;
}

k::Result<SynthesisOutcome> solve(const FunctionRequest& r, const k::DefectBounds& bounds) {
  const auto s = k::synthesiseFunction(r.target, r.options, bounds);
  if (!s) return s.error();
  SynthesisOutcome out;
  out.errorUnit = QStringLiteral("°");
  out.errorScale = k::radToDeg(1.0);
  std::vector<double> inputs;
  for (const k::AnglePair& p : s->precisionAngles) inputs.push_back(p.input);
  SynthesisRow row{s->candidate, QStringLiteral("1"), inputs.empty() ? 0.0 : inputs.front(), {}};
  row.targets.points = pointAt(s->candidate.design, k::fourbar::kC, inputs);
  out.rows.push_back(row);
  out.summary = tr("%1 precision points; structural error at most %2 (%3 in y) at x = %4")
                    .arg(s->points.size())
                    .arg(degreesText(s->error.maxAbs), numberText(s->error.maxAbsY), numberText(s->error.maxAt));
  if (!s->error.notAssembled.empty()) out.summary += tr("; it cannot be assembled over part of the range");
  return out;
}

k::Result<SynthesisOutcome> solve(const MotionRequest& r, const k::DefectBounds& bounds) {
  const auto s = r.poses.size() == 2
                     ? k::synthesiseMotion2(r.poses, r.circlePoints, r.centreA, r.centreB, bounds, r.options)
                     : k::synthesiseMotion3(r.poses, r.circlePoints, bounds, r.options);
  if (!s) return s.error();
  SynthesisOutcome out;
  out.errorUnit = QString::fromStdString(r.options.lengthUnit);
  out.exact = true;
  out.targets.poses = r.poses;
  out.targets.points = {r.circlePoints.a, r.circlePoints.b};
  out.rows.push_back({s->candidate, QStringLiteral("1"), s->crankAngles.empty() ? 0.0 : s->crankAngles.front(), {}});
  out.summary = tr("Through the %1 poses exactly; crank %2, coupler %3, rocker %4, frame %5 %6")
                    .arg(r.poses.size())
                    .arg(numberText(s->lengths.crank), numberText(s->lengths.coupler), numberText(s->lengths.rocker),
                         numberText(s->lengths.frame), out.errorUnit);
  return out;
}

}  // namespace

k::Result<SynthesisOutcome> solveClosedForm(const ClosedFormRequest& request, const k::DefectBounds& bounds) {
  return std::visit([&](const auto& r) { return solve(r, bounds); }, request);
}

SynthesisOutcome pathOutcome(const k::PathSynthesis& result, const k::PathTarget& target) {
  SynthesisOutcome out;
  out.errorUnit = QString::fromStdString(target.lengthUnit);
  out.targets.points = target.points;
  for (std::size_t i = 0; i < result.candidates.size(); ++i) {
    const k::PathCandidate& c = result.candidates[i];
    out.rows.push_back({c.candidate, QString::number(i + 1), c.crankAngles.empty() ? 0.0 : c.crankAngles.front(), {}});
  }
  out.summary = tr("%1 starts in %2 s; %3 local minima kept")
                    .arg(result.startsRun)
                    .arg(numberText(result.seconds, 'f', 2))
                    .arg(result.candidates.size());
  if (result.cancelled) out.summary += tr(" (cancelled: what was found so far)");
  if (!result.candidates.empty())
    out.summary += tr("; best within %1 %2 of every target")
                       .arg(numberText(result.candidates.front().worstDistance), out.errorUnit);
  return out;
}

}  // namespace linkwright::ui
