#include "kinematics/analysis/limit_positions.h"

#include "kinematics/analysis/grashof.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

double wrapPositive(double angle) {
  const double w = std::fmod(angle, 2.0 * kPi);
  return w < 0.0 ? w + 2.0 * kPi : w;
}

// Positions of C at distance rho from O2 = (0,0) and c from O4 = (d,0): both mirror images.
std::vector<Eigen::Vector2d> triangleApexes(double rho, double c, double d) {
  const RrrCandidates cand = rrrCandidates(Eigen::Vector2d::Zero(), rho, Eigen::Vector2d(d, 0.0), c);
  if (cand.failure != AssemblyFailure::None) return {};
  if (cand.halfSeparation == 0.0) return {cand.open};
  return {cand.open, cand.crossed};
}

// Keeps a candidate limit position only if the linkage, solved on its branch at that crank
// angle, actually puts C there.
void addIfReached(const Mechanism& m, const FourBarLengths& l, const Eigen::Vector2d& c, bool extended,
                  std::vector<LimitPosition>& out) {
  const double toC = std::atan2(c.y(), c.x());
  const double crank = extended || l.crank > l.coupler ? toC : toC + kPi;
  const Result<Pose> pose = solvePose(m, {crank, 0.0, 0.0}, {false, false});
  if (!pose) return;
  const double scale = l.frame + l.crank + l.coupler + l.rocker;
  if ((pose->position[fourbar::kC.index] - c).norm() > 1e-7 * scale) return;
  out.push_back({extended, wrapPositive(crank), pose->linkAngle[fourbar::kRocker.index]});
}

}  // namespace

LimitReport fourBarLimitPositions(const FourBarLengths& l, Branch branch) {
  LimitReport report;
  const Result<Mechanism> m = makeFourBar(l, branch);
  if (!m) return report;
  for (const Eigen::Vector2d& c : triangleApexes(l.coupler + l.crank, l.rocker, l.frame))
    addIfReached(*m, l, c, true, report.positions);
  if (l.coupler != l.crank)
    for (const Eigen::Vector2d& c : triangleApexes(std::abs(l.coupler - l.crank), l.rocker, l.frame))
      addIfReached(*m, l, c, false, report.positions);
  std::sort(report.positions.begin(), report.positions.end(),
            [](const LimitPosition& a, const LimitPosition& b) { return a.crankAngle < b.crankAngle; });

  const GrashofReport grashof = classifyGrashof(l);
  if (report.positions.size() != 2 || !grashof.inputFullyRotates || grashof.outputFullyRotates) return report;
  const LimitPosition& first = report.positions[0];
  const LimitPosition& second = report.positions[1];
  const double arc = second.crankAngle - first.crankAngle;
  report.slowStrokeCrankArc = std::max(arc, 2.0 * kPi - arc);
  report.quickStrokeCrankArc = std::min(arc, 2.0 * kPi - arc);
  report.timeRatio = *report.slowStrokeCrankArc / *report.quickStrokeCrankArc;
  report.rockerSwing = std::abs(std::remainder(second.rockerAngle - first.rockerAngle, 2.0 * kPi));
  return report;
}

}  // namespace linkwright::kinematics
