#include "kinematics/analysis/advantage_sweep.h"

#include "kinematics/analysis/centre_model.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

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

bool finiteAt(const std::vector<Ratio>& r, std::size_t j) { return j < r.size() && r[j].kind == RatioKind::Finite; }

// The ratio's size falls into the sign change between samples j and j + 1 and grows out of it:
// a zero. Through a pole it grows into the change and falls after it.
bool throughZero(const std::vector<Ratio>& r, std::size_t j) {
  const bool falls = j == 0 || !finiteAt(r, j - 1) || std::abs(r[j].value) <= std::abs(r[j - 1].value);
  const bool grows = !finiteAt(r, j + 2) || std::abs(r[j + 1].value) <= std::abs(r[j + 2].value);
  return falls && grows;
}

}  // namespace

std::vector<OutputRest> outputRests(const AdvantageSeries& series) {
  const std::vector<Ratio>& r = series.velocityRatio;
  std::vector<OutputRest> out;
  for (std::size_t j = 0; j + 1 < r.size(); ++j) {
    if (!finiteAt(r, j) || !finiteAt(r, j + 1)) continue;
    const double a = r[j].value, b = r[j + 1].value;
    if (a == 0.0) {
      if (j == 0 || !finiteAt(r, j - 1) || r[j - 1].value != 0.0) out.push_back({j, 0.0});
    } else if ((a < 0.0) != (b < 0.0) && b != 0.0 && throughZero(r, j)) {
      out.push_back({j, a / (a - b)});
    }
  }
  if (!r.empty() && finiteAt(r, r.size() - 1) && r.back().value == 0.0 &&
      (r.size() == 1 || !finiteAt(r, r.size() - 2) || r[r.size() - 2].value != 0.0))
    out.push_back({r.size() - 1, 0.0});
  return out;
}

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
