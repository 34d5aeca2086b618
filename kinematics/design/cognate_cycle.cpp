#include "kinematics/design/cognate_cycle.h"

#include "kinematics/analysis/transmission.h"
#include "kinematics/model/units.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

double angleOf(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// A link's ω from its ends' positions and velocities: r × (v2 − v1) / |r|².
double omegaOf(const Eigen::Vector2d& p1, const Eigen::Vector2d& v1, const Eigen::Vector2d& p2,
               const Eigen::Vector2d& v2) {
  const Eigen::Vector2d r = p2 - p1;
  return cross(r, v2 - v1) / r.squaredNorm();
}

}  // namespace

CognateCycle cognateCycle(const SweepResult& s, const FourBarStructure& f, PointId traced) {
  CognateCycle cycle;
  std::array<double, 3> last{};
  bool inRun = false;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.assembled(j)) {
      inRun = false;
      continue;
    }
    const FourBarJoints original{s.position[f.o2.index][j], s.position[f.o4.index][j], s.position[f.b.index][j],
                                 s.position[f.c.index][j], s.position[traced.index][j]};
    const CognateJoints built = cognateJoints(original);
    const std::array<const FourBarJoints*, 3> bars{&original, &built.first, &built.second};
    const bool fresh = !inRun || s.lockedAfter(j - 1);
    for (std::size_t k = 0; k < 3; ++k) {
      const FourBarJoints& bar = *bars[k];
      const double raw = angleOf(bar.b - bar.o2) - angleOf(bar.o4 - bar.o2);
      const double angle = fresh ? raw : last[k] + std::remainder(raw - last[k], 2.0 * kPi);
      last[k] = angle;
      if (fresh) cycle.runs[k].push_back({angle, angle, angle});
      CrankRun& run = cycle.runs[k].back();
      run.least = std::min(run.least, angle);
      run.greatest = std::max(run.greatest, angle);
    }
    inRun = true;
    if (!s.ok(j)) continue;
    const Eigen::Vector2d vb = s.velocity[f.b.index][j], vc = s.velocity[f.c.index][j];
    const double omega2 = omegaOf(original.o2, Eigen::Vector2d::Zero(), original.b, vb);
    if (omega2 == 0.0) continue;
    const double ratio = omegaOf(original.b, vb, original.c, vc) / omega2;
    cycle.couplerSpeedRatioMin = std::min(cycle.couplerSpeedRatioMin.value_or(ratio), ratio);
    cycle.couplerSpeedRatioMax = std::max(cycle.couplerSpeedRatioMax.value_or(ratio), ratio);
  }
  return cycle;
}

std::optional<double> worstTransmissionOverRuns(const FourBarLengths& lengths, const std::vector<CrankRun>& runs) {
  std::optional<double> worst;
  for (const CrankRun& run : runs) {
    const auto mu = worstTransmissionBetween(lengths, run.least, run.greatest);
    if (!mu) return std::nullopt;
    worst = std::min(worst.value_or(*mu), *mu);
  }
  return worst;
}

}  // namespace linkwright::kinematics
