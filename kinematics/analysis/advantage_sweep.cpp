#include "kinematics/analysis/advantage_sweep.h"

#include "kinematics/solve/pose_solver.h"

namespace linkwright::kinematics {

Result<AdvantageSeries> advantageSeries(const Mechanism& m, const SweepResult& sweep) {
  const std::size_t n = sweep.size();
  if (sweep.position.size() != m.points.size())
    return Error{ErrorCode::InvalidStructure, "sweep",
                 "the sweep holds positions of " + std::to_string(sweep.position.size()) +
                     " points but the mechanism has " + std::to_string(m.points.size())};
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (sweep.position[i].size() != n)
      return Error{ErrorCode::InvalidStructure, "sweep",
                   "the sweep has no positions of point " + m.points[i].name + " (sweep every point)"};
  Pose pose;
  preparePose(m, pose);
  AdvantageSeries out;
  out.velocityRatio.resize(n, Ratio{RatioKind::Undefined, 0.0});
  out.advantage.resize(n, Ratio{RatioKind::Undefined, 0.0});
  bool kindKnown = false;
  for (std::size_t j = 0; j < n; ++j) {
    if (!sweep.assembled(j)) continue;
    for (std::size_t i = 0; i < m.points.size(); ++i) pose.position[i] = sweep.position[i][j];
    const auto centres = instantCentres(m, pose);
    if (!centres) return centres.error();
    out.linkage = centres->linkage;
    kindKnown = true;
    const MechanicalAdvantage ma = mechanicalAdvantage(*centres);
    out.velocityRatio[j] = ma.velocityRatio;
    out.advantage[j] = ma.advantage;
  }
  if (!kindKnown) {
    // Nothing assembled: still say what the mechanism is, or refuse it as instantCentres does.
    const auto centres = instantCentres(m, pose);
    if (!centres && centres.error().code == ErrorCode::InvalidStructure) return centres.error();
    if (centres) out.linkage = centres->linkage;
  }
  return out;
}

}  // namespace linkwright::kinematics
