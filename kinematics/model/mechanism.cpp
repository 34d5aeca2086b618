#include "kinematics/model/mechanism.h"

namespace linkwright::kinematics {

std::optional<PointId> Mechanism::findPoint(const std::string& name) const {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].name == name) return PointId{i};
  return std::nullopt;
}

std::optional<LinkId> Mechanism::findLink(const std::string& name) const {
  for (std::size_t i = 0; i < links.size(); ++i)
    if (links[i].name == name) return LinkId{i};
  return std::nullopt;
}

std::vector<std::size_t> transmissionJoints(const Mechanism& m) {
  std::vector<std::size_t> joints;
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (hasTransmissionAngle(m.points[i].definition)) joints.push_back(i);
  return joints;
}

}  // namespace linkwright::kinematics
