#include "kinematics/analysis/centrodes.h"

#include "kinematics/analysis/centre_model.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace linkwright::kinematics {

namespace {

Result<CentreModel> floatingBodyModel(const Mechanism& mechanism) {
  auto model = centreModel(mechanism);
  if (model && model->centrodeBody == 0)
    return Error{ErrorCode::InvalidStructure, "mechanism",
                 "centrodes are traced for a body not jointed to the frame (a coupler): every body of this linkage "
                 "is jointed to it"};
  return model;
}

}  // namespace

Eigen::Vector2d CouplerFrame::toWorld(const Eigen::Vector2d& local) const {
  const double c = std::cos(angle), s = std::sin(angle);
  return b + Eigen::Vector2d(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}

Eigen::Vector2d CouplerFrame::toLocal(const Eigen::Vector2d& world) const {
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector2d d = world - b;
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

CouplerFrame couplerFrame(const CentreModel& model, const Pose& pose) {
  const Eigen::Vector2d b = pose.position[model.centrodeFirst.index], c = pose.position[model.centrodeSecond.index];
  return CouplerFrame{b, std::atan2(c.y() - b.y(), c.x() - b.x())};
}

Result<CouplerFrame> couplerFrame(const Mechanism& mechanism, const Pose& pose) {
  const auto model = floatingBodyModel(mechanism);
  if (!model) return model.error();
  return couplerFrame(*model, pose);
}

Result<Centrodes> centrodes(const Mechanism& mechanism, const SweepResult& sweep) {
  const auto model = floatingBodyModel(mechanism);
  if (!model) return model.error();
  const bool complete = sweep.position.size() == mechanism.points.size() &&
                        std::all_of(sweep.position.begin(), sweep.position.end(),
                                    [&](const auto& column) { return column.size() >= sweep.size(); });
  if (!complete)
    return Error{ErrorCode::InvalidValue, "sweep", "centrodes need every point's position at every sample"};
  Centrodes out;
  out.body = model->centrodeBody;
  bool inRun = false;
  InstantCentres centres;  // reused from sample to sample
  Pose pose;               // positions only: the centres need nothing else
  pose.position.resize(mechanism.points.size());
  for (std::size_t j = 0; j < sweep.size(); ++j) {
    std::optional<Eigen::Vector2d> centre;
    if (sweep.assembled(j)) {
      for (std::size_t i = 0; i < pose.position.size(); ++i) pose.position[i] = sweep.position[i][j];
      instantCentresInto(mechanism, *model, pose, centres);
      const InstantCentre& i1k = centres.centre(1, out.body);
      if (i1k.kind == CentreKind::Finite && (i1k.position - centres.anchor).norm() <= kCentrodeReach * centres.scale)
        centre = i1k.position;
    }
    if (!centre) {
      inRun = false;
      continue;
    }
    if (!inRun) {
      out.fixed.emplace_back();
      out.moving.emplace_back();
      inRun = true;
    }
    out.fixed.back().push_back(*centre);
    out.moving.back().push_back(couplerFrame(*model, pose).toLocal(*centre));
  }
  return out;
}

}  // namespace linkwright::kinematics
