#include "kinematics/analysis/advantage_sweep.h"

#include "kinematics/analysis/centre_model.h"
#include "kinematics/solve/pose_solver.h"

namespace linkwright::kinematics {
namespace {

Result<CentreModel> ratioModel(const Mechanism& m) {
  auto model = centreModel(m);
  if (!model || model->ratio.exists()) return model;
  const std::string missing = model->ratio.input == 0 ? "it is not driven by a crank turning about a frame pin"
                                                      : "no other body is jointed to the frame";
  return Error{
      ErrorCode::InvalidStructure, "mechanism",
      "the velocity ratio and mechanical advantage compare a crank with an output jointed to the frame: " + missing};
}

}  // namespace

std::optional<Error> ratioUnavailable(const Mechanism& m) {
  const auto model = ratioModel(m);
  if (!model) return model.error();
  return std::nullopt;
}

Result<AdvantageSeries> advantageSeries(const Mechanism& m, const SweepResult& sweep) {
  const auto model = ratioModel(m);
  if (!model) return model.error();
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
  out.bodies = model->ratio;
  out.velocityRatio.resize(n, Ratio{RatioKind::Undefined, 0.0});
  out.advantage.resize(n, Ratio{RatioKind::Undefined, 0.0});
  InstantCentres centres;  // reused: one allocation for the sweep, not one per sample
  for (std::size_t j = 0; j < n; ++j) {
    if (!sweep.assembled(j)) continue;
    for (std::size_t i = 0; i < m.points.size(); ++i) pose.position[i] = sweep.position[i][j];
    instantCentresInto(m, *model, pose, centres);
    const MechanicalAdvantage ma = mechanicalAdvantage(centres);
    out.velocityRatio[j] = ma.velocityRatio;
    out.advantage[j] = ma.advantage;
  }
  return out;
}

}  // namespace linkwright::kinematics
