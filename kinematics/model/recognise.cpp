#include "kinematics/model/recognise.h"

#include "kinematics/model/work_count.h"

#include <cmath>
#include <variant>

namespace linkwright::kinematics {
namespace {

// Null for another kind of point, or for an id past the end (an unchecked mechanism: the
// recognisers may be asked before checkMechanism).
template <typename T>
const T* definitionOf(const Mechanism& m, PointId id) {
  return id.index < m.points.size() ? std::get_if<T>(&m.points[id.index].definition) : nullptr;
}

// The one crank point and its ground pivot.
std::optional<PointId> crankPoint(const Mechanism& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (const auto* crank = std::get_if<CrankPoint>(&m.points[i].definition))
      return definitionOf<GroundPoint>(m, crank->pivot) ? std::optional(PointId{i}) : std::nullopt;
  return std::nullopt;
}

bool joins(const Link& link, PointId a, PointId b) {
  return (link.first == a && link.second == b) || (link.first == b && link.second == a);
}

// Whether point `id`, fixed on a link, is one the recogniser allows: on the link B–C, or on
// any link when `allowed` says so.
bool allowedRider(const Mechanism& m, PointId id, PointId b, PointId c, PointsOnLinks allowed) {
  const auto* attached = definitionOf<AttachedPoint>(m, id);
  if (!attached || attached->link.index >= m.links.size()) return false;
  return allowed == PointsOnLinks::AnyLink || joins(m.links[attached->link.index], b, c);
}

}  // namespace

std::optional<FourBarStructure> asFourBar(const Mechanism& m, PointsOnLinks allowed) {
  countRecognition();
  if (!m.constraints.empty()) return std::nullopt;
  const auto b = crankPoint(m);
  if (!b) return std::nullopt;
  const CrankPoint& crank = *definitionOf<CrankPoint>(m, *b);
  std::optional<FourBarStructure> found;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointId id{i};
    if (id == *b || definitionOf<GroundPoint>(m, id)) continue;
    const auto* rrr = definitionOf<RrrPoint>(m, id);
    if (rrr && !found) {
      // C on B and a ground pivot other than O2, either way round.
      const bool bFirst = rrr->first == *b;
      const PointId other = bFirst ? rrr->second : rrr->first;
      if ((bFirst || rrr->second == *b) && other != crank.pivot && definitionOf<GroundPoint>(m, other)) {
        FourBarStructure s;
        s.o2 = crank.pivot;
        s.o4 = other;
        s.b = *b;
        s.c = id;
        const Eigen::Vector2d frame =
            definitionOf<GroundPoint>(m, other)->position - definitionOf<GroundPoint>(m, crank.pivot)->position;
        s.lengths = {frame.norm(), crank.length, bFirst ? rrr->firstLength : rrr->secondLength,
                     bFirst ? rrr->secondLength : rrr->firstLength};
        // The dyad's open side is left of first→second; the four-bar's is left of B→O4.
        s.branch = bFirst ? rrr->branch : (rrr->branch == Branch::Open ? Branch::Crossed : Branch::Open);
        s.frameAngle = std::atan2(frame.y(), frame.x());
        s.crankPhase = crank.phase;
        found = s;
        continue;
      }
    }
    // Anything else must be a point fixed on the coupler B–C (or, if allowed, any link).
    if (!found || !allowedRider(m, id, found->b, found->c, allowed)) return std::nullopt;
  }
  return found;
}

std::optional<SliderCrankStructure> asSliderCrank(const Mechanism& m, PointsOnLinks allowed) {
  if (!m.constraints.empty()) return std::nullopt;
  const auto b = crankPoint(m);
  if (!b) return std::nullopt;
  const PointId o2 = definitionOf<CrankPoint>(m, *b)->pivot;
  std::optional<SliderCrankStructure> found;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointId id{i};
    if (id == *b || definitionOf<GroundPoint>(m, id)) continue;
    const auto* slider = definitionOf<RrpPoint>(m, id);
    if (slider && !found && slider->first == *b && !slider->guide.link) {
      found = SliderCrankStructure{o2, *b, id, slider->guide.angle};
      continue;
    }
    if (!found || !allowedRider(m, id, found->b, found->c, allowed)) return std::nullopt;
  }
  return found;
}

std::optional<QuickReturnStructure> asQuickReturn(const Mechanism& m) {
  if (m.points.size() != 5 || !m.constraints.empty()) return std::nullopt;
  const auto b = crankPoint(m);
  if (!b) return std::nullopt;
  const CrankPoint& crank = *definitionOf<CrankPoint>(m, *b);
  if (crank.phase != 0.0) return std::nullopt;
  for (std::size_t d = 0; d < m.points.size(); ++d) {
    const auto* slot = definitionOf<RprPoint>(m, PointId{d});
    if (!slot || slot->through != *b || !definitionOf<GroundPoint>(m, slot->pivot)) continue;
    for (std::size_t r = 0; r < m.points.size(); ++r) {
      const auto* ram = definitionOf<RrpPoint>(m, PointId{r});
      // shaperQuickReturn's ram guide is horizontal and fixed to the ground.
      if (!ram || ram->first != PointId{d} || ram->guide.link || ram->guide.angle != 0.0) continue;
      const Eigen::Vector2d o2 = definitionOf<GroundPoint>(m, crank.pivot)->position;
      const Eigen::Vector2d o4 = definitionOf<GroundPoint>(m, slot->pivot)->position;
      return QuickReturnStructure{{crank.length, slot->length, ram->length, o4 - o2, ram->guide.point.y() - o2.y()},
                                  ram->branch};
    }
  }
  return std::nullopt;
}

}  // namespace linkwright::kinematics
