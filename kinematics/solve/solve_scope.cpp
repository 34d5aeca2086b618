#include "kinematics/solve/solve_scope.h"

#include "kinematics/model/constraint_form.h"

#include <string>

namespace linkwright::kinematics {
namespace {

std::vector<unsigned char> marks(std::size_t count, const auto& selected) {
  std::vector<unsigned char> out(count, selected ? 0 : 1);
  if (selected)
    for (const auto id : *selected) out[id.index] = 1;
  return out;
}

// Marks what point i is defined from (all earlier than i, or links between earlier points).
class Closure {
public:
  Closure(const Mechanism& m, SolveScope& s) : m_mech(m), m_scope(s) {}

  void needLink(LinkId k) {
    m_scope.solveLink[k.index] = 1;
    m_scope.solvePoint[m_mech.links[k.index].first.index] = 1;
    m_scope.solvePoint[m_mech.links[k.index].second.index] = 1;
  }

  void needGuide(const Guide& g) {
    if (g.link) needLink(*g.link);
  }

  void needDefinitionOf(std::size_t i) {
    auto need = [&](PointId p) { m_scope.solvePoint[p.index] = 1; };
    const PointDefinition& def = m_mech.points[i].definition;
    if (const auto* c = std::get_if<CrankPoint>(&def)) need(c->pivot);
    else if (const auto* actuator = std::get_if<ActuatorPoint>(&def)) {
      need(actuator->first);
      need(actuator->base);
    } else if (const auto* r = std::get_if<RrrPoint>(&def)) {
      need(r->first);
      need(r->second);
    } else if (const auto* p = std::get_if<RrpPoint>(&def)) {
      need(p->first);
      needGuide(p->guide);
    } else if (const auto* s = std::get_if<RprPoint>(&def)) {
      need(s->pivot);
      need(s->through);
    } else if (const auto* q = std::get_if<PrpPoint>(&def)) {
      needGuide(q->first);
      needGuide(q->second);
    } else if (const auto* a = std::get_if<AttachedPoint>(&def)) needLink(a->link);
  }

  // A free group is solved whole, so one needed member needs all members and every point its
  // constraints reach.
  void needFreeGroupOf(std::size_t i) {
    std::size_t first = i;
    while (first > 0 && isFreePoint(m_mech, PointId{first - 1})) --first;
    const std::size_t last = freeGroupEnd(m_mech, first);
    for (std::size_t j = first; j < last; ++j) m_scope.solvePoint[j] = 1;
    for (const DistanceConstraint& c : m_mech.constraints) {
      const std::size_t later = constraintLaterPoint(c).index;
      if (later < first || later >= last) continue;
      m_scope.solvePoint[c.first.index] = 1;
      m_scope.solvePoint[c.second.index] = 1;
    }
  }

private:
  const Mechanism& m_mech;
  SolveScope& m_scope;
};

}  // namespace

std::optional<Error> checkSelection(const Mechanism& m, const Selection& selection) {
  if (selection.points)
    for (std::size_t j = 0; j < selection.points->size(); ++j)
      if ((*selection.points)[j].index >= m.points.size())
        return Error{ErrorCode::InvalidStructure, "only.points[" + std::to_string(j) + "]",
                     "only.points[" + std::to_string(j) + "] is point " + std::to_string((*selection.points)[j].index) +
                         ", but the mechanism has " + std::to_string(m.points.size()) + " points"};
  if (selection.links)
    for (std::size_t j = 0; j < selection.links->size(); ++j)
      if ((*selection.links)[j].index >= m.links.size())
        return Error{ErrorCode::InvalidStructure, "only.links[" + std::to_string(j) + "]",
                     "only.links[" + std::to_string(j) + "] is link " + std::to_string((*selection.links)[j].index) +
                         ", but the mechanism has " + std::to_string(m.links.size()) + " links"};
  return std::nullopt;
}

SolveScope scopeOf(const Mechanism& m, const Selection& selection) {
  SolveScope s;
  s.reportPoint = marks(m.points.size(), selection.points);
  s.reportLink = marks(m.links.size(), selection.links);
  s.solvePoint = s.reportPoint;
  s.solveLink = s.reportLink;
  Closure closure(m, s);
  for (std::size_t k = 0; k < m.links.size(); ++k)
    if (s.solveLink[k]) closure.needLink(LinkId{k});
  for (std::size_t i = m.points.size(); i-- > 0;) {
    if (!s.solvePoint[i]) continue;
    if (isFreePoint(m, PointId{i})) closure.needFreeGroupOf(i);
    closure.needDefinitionOf(i);
  }
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (!s.solvePoint[i] || std::holds_alternative<GroundPoint>(m.points[i].definition)) continue;
    s.pointSteps.push_back(PointId{i});
    if (isFreePoint(m, PointId{i})) i = freeGroupEnd(m, i) - 1;
  }
  for (std::size_t k = 0; k < m.links.size(); ++k)
    if (s.solveLink[k]) s.linkSteps.push_back({LinkId{k}, crankPhaseOf(m, LinkId{k})});
  return s;
}

}  // namespace linkwright::kinematics
