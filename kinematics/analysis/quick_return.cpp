#include "kinematics/analysis/quick_return.h"

#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics {

std::optional<QuickReturnReport> shaperQuickReturn(const ShaperGeometry& g, Branch branch) {
  const auto m = makeShaper(g, branch);
  if (!m) return std::nullopt;
  const double d = g.rockerPivot.norm();
  if (d <= g.crank) return std::nullopt;
  const double psi = std::atan2(g.rockerPivot.y(), g.rockerPivot.x());
  const double half = std::acos(g.crank / d);
  QuickReturnReport r;
  const auto wrap = [](double a) { return a - 2.0 * kPi * std::floor(a / (2.0 * kPi)); };
  r.firstLimitCrankAngle = wrap(psi - half);
  r.secondLimitCrankAngle = wrap(psi + half);
  r.slowStrokeCrankArc = std::max(2.0 * half, 2.0 * kPi - 2.0 * half);
  r.quickStrokeCrankArc = std::min(2.0 * half, 2.0 * kPi - 2.0 * half);
  r.timeRatio = r.slowStrokeCrankArc / r.quickStrokeCrankArc;
  const auto first = solvePose(*m, {r.firstLimitCrankAngle, 0.0, 0.0}, {false, false});
  const auto second = solvePose(*m, {r.secondLimitCrankAngle, 0.0, 0.0}, {false, false});
  if (!first || !second) return std::nullopt;
  r.rockerSwing = std::abs(std::remainder(first->linkAngle[shaper::kRocker.index] - second->linkAngle[shaper::kRocker.index], 2.0 * kPi));
  r.stroke = std::abs(first->position[shaper::kRam.index].x() - second->position[shaper::kRam.index].x());
  return r;
}

} // namespace linkwright::kinematics
