#include "kinematics/explore/cognate_cycle.h"

#include "kinematics/analysis/assembly_range.h"
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

// `angle` (rad) moved to the nearest edge of `range` in any turn, if one is within `reach`.
double snappedToEdge(double angle, const InputRange& range, double reach) {
  double best = angle, nearest = reach;
  for (const AngleRange& r : range.ranges)
    for (const double edge : {r.from, r.to}) {
      const double step = std::remainder(edge - angle, 2.0 * kPi);
      if (std::abs(step) < nearest) {
        nearest = std::abs(step);
        best = angle + step;
      }
    }
  return best;
}

}  // namespace

CognateCycle cognateCycle(const SweepResult& s, const FourBarStructure& f, PointId traced) {
  CognateCycle cycle;
  // Per four-bar: the last angle, and the samples of the current run's first, least and
  // greatest angle.
  std::array<double, 3> last{};
  std::array<std::array<std::size_t, 3>, 3> at{};
  bool inRun = false;
  // Only on an angle grid does the original's crank never turn back itself.
  const bool grid = s.time.empty();
  const auto closeRun = [&](std::size_t lastSample) {
    for (std::size_t k = 0; k < 3; ++k) {
      CrankRun& run = cycle.runs[k].back();
      const auto inside = [&](std::size_t j) { return grid && j != at[k][0] && j != lastSample; };
      run.turnsBackAtLeast = inside(at[k][1]);
      run.turnsBackAtGreatest = inside(at[k][2]);
    }
  };
  for (std::size_t j = 0; j < s.size(); ++j) {
    const bool fresh = !inRun || !s.assembled(j) || s.lockedAfter(j - 1);
    if (inRun && fresh) closeRun(j - 1);
    inRun = s.assembled(j);
    if (!inRun) continue;
    const FourBarJoints original{s.position[f.o2.index][j], s.position[f.o4.index][j], s.position[f.b.index][j],
                                 s.position[f.c.index][j], s.position[traced.index][j]};
    const CognateJoints built = cognateJoints(original);
    const std::array<const FourBarJoints*, 3> bars{&original, &built.first, &built.second};
    for (std::size_t k = 0; k < 3; ++k) {
      const FourBarJoints& bar = *bars[k];
      const double raw = angleOf(bar.b - bar.o2) - angleOf(bar.o4 - bar.o2);
      const double angle = fresh ? raw : last[k] + std::remainder(raw - last[k], 2.0 * kPi);
      last[k] = angle;
      if (fresh) {
        cycle.runs[k].push_back({angle, angle, angle});
        at[k] = {j, j, j};
      }
      CrankRun& run = cycle.runs[k].back();
      if (angle < run.least) {
        run.least = angle;
        at[k][1] = j;
      }
      if (angle > run.greatest) {
        run.greatest = angle;
        at[k][2] = j;
      }
    }
    if (!s.ok(j)) continue;
    const Eigen::Vector2d vb = s.velocity[f.b.index][j], vc = s.velocity[f.c.index][j];
    const double omega2 = omegaOf(original.o2, Eigen::Vector2d::Zero(), original.b, vb);
    if (omega2 == 0.0) continue;
    const double ratio = omegaOf(original.b, vb, original.c, vc) / omega2;
    cycle.couplerSpeedRatioMin = std::min(cycle.couplerSpeedRatioMin.value_or(ratio), ratio);
    cycle.couplerSpeedRatioMax = std::max(cycle.couplerSpeedRatioMax.value_or(ratio), ratio);
  }
  if (inRun) closeRun(s.size() - 1);
  return cycle;
}

std::optional<double> worstTransmissionOverRuns(const FourBarLengths& lengths, const std::vector<CrankRun>& runs) {
  const InputRange range = fourBarInputRange(lengths);
  std::optional<double> worst;
  for (const CrankRun& run : runs) {
    // The sampled extreme lies inside the true one by about the square of a sample's step.
    const double reach = 1e-2;
    const double least = run.turnsBackAtLeast ? snappedToEdge(run.least, range, reach) : run.least;
    const double greatest = run.turnsBackAtGreatest ? snappedToEdge(run.greatest, range, reach) : run.greatest;
    const auto mu = worstTransmissionBetween(lengths, least, greatest);
    if (!mu) return std::nullopt;
    worst = std::min(worst.value_or(*mu), *mu);
  }
  return worst;
}

}  // namespace linkwright::kinematics
