#pragma once
// Test helper: sweeps a mechanism, evaluates a quantity at every sample where the pose is ok,
// and refines the quantity's extremes (kinematics/analysis/extrema.h).

#include "kinematics/analysis/extrema.h"
#include "kinematics/solve/pose_solver.h"

#include "tests/support/catch.h"

#include <vector>

namespace linkwright::test {

inline kinematics::Extrema extremaOf(const kinematics::Mechanism& m, const kinematics::SweepSpec& spec,
                                     const kinematics::PoseQuantity& q) {
  using namespace kinematics;
  const auto s = sweep(m, spec);
  REQUIRE(s.ok());
  std::vector<double> values(s->size(), 0.0);
  std::vector<bool> valid(s->size(), false);
  Pose pose;
  preparePose(m, pose);
  for (std::size_t j = 0; j < s->size(); ++j) {
    valid[j] = s->ok(j);
    if (!valid[j]) continue;
    REQUIRE(solvePoseInto(m, {s->inputAngle[j], spec.omega, spec.alpha}, {true, true}, pose).status == PoseStatus::Ok);
    values[j] = q(pose, s->inputAngle[j]);
  }
  const auto e = refineExtrema(m, spec, values, valid, q);
  REQUIRE(e.has_value());
  return *e;
}

}  // namespace linkwright::test
