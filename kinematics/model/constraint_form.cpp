#include "kinematics/model/constraint_form.h"

#include <cassert>

namespace linkwright::kinematics {

bool isFreePoint(const Mechanism& m, PointId id) {
  return std::holds_alternative<FreePoint>(m.points[id.index].definition);
}

std::size_t freeGroupEnd(const Mechanism& m, std::size_t first) {
  std::size_t last = first;
  while (last < m.points.size() && isFreePoint(m, PointId{last})) ++last;
  return last;
}

Mechanism withNewtonPoints(const Mechanism& mechanism, std::span<const Eigen::Vector2d> positions) {
  assert(positions.size() == mechanism.points.size());
  Mechanism out = mechanism;
  for (std::size_t i = 0; i < out.points.size(); ++i) {
    const auto* r = std::get_if<RrrPoint>(&out.points[i].definition);
    if (r == nullptr) continue;
    // Parents first, the point second: the constraint's later point is this one.
    out.constraints.push_back({r->first, PointId{i}, r->firstLength});
    out.constraints.push_back({r->second, PointId{i}, r->secondLength});
    out.points[i].definition = FreePoint{positions[i]};
  }
  return out;
}

}  // namespace linkwright::kinematics
