#include "kinematics/analysis/mobility.h"

#include "kinematics/model/constraint_form.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace linkwright::kinematics {
namespace {

std::size_t findRoot(std::vector<std::size_t>& parent, std::size_t k) {
  while (parent[k] != k) k = parent[k] = parent[parent[k]];
  return k;
}

bool joined(const DistanceConstraint& c, PointId a, PointId b) {
  return (c.first == a && c.second == b) || (c.first == b && c.second == a);
}

// Free points are held by distances alone, which do not say which bars form one body. We take
// each distance as a binary link, except that distances closing a triangle are one rigid
// plate, and triangles sharing a side one plate (a triangulated plate): the textbook counts
// for plates given by their three sides (Stephenson III: N = 6, jp = 7). A pin where b bodies
// meet is b − 1 joints; at a free point the bodies are the group's, at any other point the
// body already there (ground, crank, dyad link) is one more, so each group body adds a joint.
// Bars and triangles count exactly as the distances do (a triangle of three pinned bars is
// rigid): a group of k points and c distances adds 2k − c to M, 0 for a valid group (c = 2k),
// as a dyad does. Only a plate with a redundant side (a braced quadrilateral, K4) counts as one
// body where its distances say one less; such a group's Jacobian is singular anyway.
void countFreeBodies(const Mechanism& m, MobilityReport& r) {
  const std::size_t n = m.constraints.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const DistanceConstraint& a = m.constraints[i];
      const DistanceConstraint& b = m.constraints[j];
      // Two sides sharing a vertex close a triangle if a third side joins their other ends.
      const bool atFirst = a.first == b.first || a.first == b.second;
      if (!atFirst && a.second != b.first && a.second != b.second) continue;
      const PointId shared = atFirst ? a.first : a.second;
      const PointId x = atFirst ? a.second : a.first;
      const PointId y = b.first == shared ? b.second : b.first;
      for (std::size_t k = 0; k < n; ++k)
        if (joined(m.constraints[k], x, y)) {
          parent[findRoot(parent, i)] = findRoot(parent, k);
          parent[findRoot(parent, j)] = findRoot(parent, k);
        }
    }
  // For every point, the distinct bodies (roots) touching it.
  std::vector<std::vector<std::size_t>> bodiesAt(m.points.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t root = findRoot(parent, k);
    if (root == k) r.links += 1;
    for (const PointId p : {m.constraints[k].first, m.constraints[k].second}) {
      std::vector<std::size_t>& at = bodiesAt[p.index];
      if (std::find(at.begin(), at.end(), root) == at.end()) at.push_back(root);
    }
  }
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const int bodies = static_cast<int>(bodiesAt[i].size());
    if (bodies > 0) r.fullJoints += isFreePoint(m, PointId{i}) ? bodies - 1 : bodies;
  }
}

}  // namespace

int grueblerMobility(int links, int fullJoints, int halfJoints) {
  return 3 * (links - 1) - 2 * fullJoints - halfJoints;
}

MobilityReport mobility(const Mechanism& m) {
  MobilityReport r;
  r.links = 1;  // the ground
  for (const Point& p : m.points) {
    if (std::holds_alternative<CrankPoint>(p.definition) || std::holds_alternative<PathPoint>(p.definition)) {
      // The crank and its pivot; or the block that carries a driven point along its path, in
      // its (straight or curved) slot.
      r.links += 1;
      r.fullJoints += 1;
    } else if (std::holds_alternative<ActuatorPoint>(p.definition)) {
      // The driven link, the cylinder and its rod: pins at the link's parent, at the end and
      // at the base, and the cylinder's sliding joint.
      r.links += 3;
      r.fullJoints += 4;
    } else if (std::holds_alternative<RrrPoint>(p.definition) || std::holds_alternative<RrpPoint>(p.definition) ||
               std::holds_alternative<RprPoint>(p.definition) || std::holds_alternative<PrpPoint>(p.definition)) {
      // Two links and three joints: pin, pin, pin (RRR); pin, pin, slider (RRP); pin, slider,
      // pin (RPR: the block on the pin and the slotted link); slider, pin, slider (PRP).
      r.links += 2;
      r.fullJoints += 3;
    }
  }
  countFreeBodies(m, r);
  r.mobility = grueblerMobility(r.links, r.fullJoints, r.halfJoints);
  return r;
}

}  // namespace linkwright::kinematics
