#pragma once
// The points a load can be fixed to: each link's joints and the points attached to it, named
// as the core's loads name them (a link and a point), in the mechanism's order. The dynamics
// panel offers them for a point force and for a spring's ends.

#include "kinematics/model/mechanism.h"

#include <string>
#include <variant>
#include <vector>

namespace linkwright::ui {

struct LinkPoint {
  std::string link;  ///< the link whose body holds the point
  std::string point;
};

inline std::vector<LinkPoint> pointsOnLinks(const kinematics::Mechanism& m) {
  std::vector<LinkPoint> out;
  for (std::size_t li = 0; li < m.links.size(); ++li) {
    const kinematics::Link& link = m.links[li];
    std::vector<kinematics::PointId> on = {link.first, link.second};
    for (std::size_t p = 0; p < m.points.size(); ++p)
      if (const auto* a = std::get_if<kinematics::AttachedPoint>(&m.points[p].definition);
          a != nullptr && a->link.index == li)
        on.push_back(kinematics::PointId{p});
    for (const kinematics::PointId p : on) out.push_back({link.name, m.points[p.index].name});
  }
  return out;
}

}  // namespace linkwright::ui
