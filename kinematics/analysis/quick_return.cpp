#include "kinematics/analysis/quick_return.h"

#include "kinematics/model/units.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>
#include <vector>

namespace linkwright::kinematics {

namespace {

double wrapTurn(double a) { return a - 2.0 * kPi * std::floor(a / (2.0 * kPi)); }

// Fills the arcs and ratio from the two limit crank angles, and the stroke and slotted link's
// swing from the poses there.
std::optional<QuickReturnReport> fromLimits(const Mechanism& m, double first, double second, bool whitworth) {
  QuickReturnReport r;
  r.whitworth = whitworth;
  r.firstLimitCrankAngle = wrapTurn(first);
  r.secondLimitCrankAngle = wrapTurn(second);
  const double arc = wrapTurn(r.secondLimitCrankAngle - r.firstLimitCrankAngle);
  r.slowStrokeCrankArc = std::max(arc, 2.0 * kPi - arc);
  r.quickStrokeCrankArc = std::min(arc, 2.0 * kPi - arc);
  r.timeRatio = r.slowStrokeCrankArc / r.quickStrokeCrankArc;
  const auto a = solvePose(m, {r.firstLimitCrankAngle, 0.0, 0.0}, {false, false});
  const auto b = solvePose(m, {r.secondLimitCrankAngle, 0.0, 0.0}, {false, false});
  if (!a || !b) return std::nullopt;
  r.rockerSwing = whitworth
                      ? 2.0 * kPi
                      : std::abs(std::remainder(
                            a->linkAngle[shaper::kRocker.index] - b->linkAngle[shaper::kRocker.index], 2.0 * kPi));
  r.stroke = std::abs(a->position[shaper::kRam.index].x() - b->position[shaper::kRam.index].x());
  return r;
}

// The crank angle that sets the slotted link at angle φ: B on the ray O4 + t·e(φ), t > 0, on
// the crank circle. With O4 inside the circle the quadratic's roots have opposite signs, so
// exactly one is positive.
double crankAngleForSlot(const ShaperGeometry& g, double phi) {
  const Eigen::Vector2d e(std::cos(phi), std::sin(phi));
  const double b = e.dot(g.rockerPivot);
  const double c = g.rockerPivot.squaredNorm() - g.crank * g.crank;
  const Eigen::Vector2d pin = g.rockerPivot + (-b + std::sqrt(b * b - c)) * e;
  return std::atan2(pin.y(), pin.x());
}

// Whitworth: the ram stops where link D→R lies along the slotted link (O4, D, R collinear),
// R = O4 + s·e(φ) with s = a ± l on the guide: sin φ = (h − O4y)/s. Of those, the branch keeps
// the ones with R on its side of D: (s − a)·cos φ > 0 for Open.
std::optional<QuickReturnReport> whitworthQuickReturn(const ShaperGeometry& g, Branch branch, const Mechanism& m) {
  std::vector<double> limits;
  for (const double s : {g.rocker + g.link, g.rocker - g.link}) {
    if (s == 0.0) continue;
    const double q = (g.guideHeight - g.rockerPivot.y()) / s;
    if (std::abs(q) > 1.0) continue;
    for (const double phi : {std::asin(q), kPi - std::asin(q)}) {
      const double side = (s - g.rocker) * std::cos(phi);
      if ((branch == Branch::Open ? side : -side) > 0.0) limits.push_back(crankAngleForSlot(g, phi));
    }
  }
  if (limits.size() != 2) return std::nullopt;
  return fromLimits(m, limits[0], limits[1], true);
}

}  // namespace

std::optional<QuickReturnReport> shaperQuickReturn(const ShaperGeometry& g, Branch branch) {
  const auto m = makeShaper(g, branch);
  if (!m) return std::nullopt;
  const double d = g.rockerPivot.norm();
  if (d < g.crank) return whitworthQuickReturn(g, branch, *m);
  const double psi = std::atan2(g.rockerPivot.y(), g.rockerPivot.x());
  const double half = std::acos(g.crank / d);
  return fromLimits(*m, psi - half, psi + half, false);
}

}  // namespace linkwright::kinematics
