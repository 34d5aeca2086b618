#include "kinematics/design/fourbar_dimensions.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

std::optional<LinkId> couplerLink(const Mechanism& m, const FourBarStructure& s) {
  for (std::size_t i = 0; i < m.links.size(); ++i) {
    const Link& l = m.links[i];
    if ((l.first == s.b && l.second == s.c) || (l.first == s.c && l.second == s.b)) return LinkId{i};
  }
  return std::nullopt;
}

// Offsets on a link running C→B restated along B→C, and back (the map is its own inverse).
CouplerPointSpec flipped(const CouplerPointSpec& p, double coupler) { return {coupler - p.along, -p.across}; }

RrrPoint& jointC(Mechanism& m, const FourBarStructure& s) { return std::get<RrrPoint>(m.points[s.c.index].definition); }

}  // namespace

std::optional<CouplerPoint> couplerPointOf(const Mechanism& m, const FourBarStructure& s) {
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const auto* a = std::get_if<AttachedPoint>(&m.points[i].definition);
    if (a == nullptr) continue;
    const CouplerPointSpec spec{a->along, a->across};
    const bool fromB = m.links[a->link.index].first == s.b;
    return CouplerPoint{PointId{i}, fromB ? spec : flipped(spec, s.lengths.coupler)};
  }
  return std::nullopt;
}

Mechanism withFourBarLengths(const Mechanism& mechanism, const FourBarStructure& s, const FourBarLengths& lengths) {
  Mechanism m = mechanism;
  const Eigen::Vector2d o2 = std::get<GroundPoint>(m.points[s.o2.index].definition).position;
  std::get<GroundPoint>(m.points[s.o4.index].definition).position =
      o2 + lengths.frame * Eigen::Vector2d(std::cos(s.frameAngle), std::sin(s.frameAngle));
  std::get<CrankPoint>(m.points[s.b.index].definition).length = lengths.crank;
  RrrPoint& c = jointC(m, s);
  const bool bFirst = c.first == s.b;
  c.firstLength = bFirst ? lengths.coupler : lengths.rocker;
  c.secondLength = bFirst ? lengths.rocker : lengths.coupler;
  // A point on a coupler link that runs C→B keeps its place relative to B.
  if (const auto p = couplerPointOf(mechanism, s); p && lengths.coupler != s.lengths.coupler) {
    auto& a = std::get<AttachedPoint>(m.points[p->id.index].definition);
    if (m.links[a.link.index].first != s.b) a.along = flipped(p->spec, lengths.coupler).along;
  }
  return m;
}

Mechanism withFourBarBranch(const Mechanism& mechanism, const FourBarStructure& s, Branch branch) {
  Mechanism m = mechanism;
  RrrPoint& c = jointC(m, s);
  // The dyad's open side is left of first→second; the four-bar's is left of B→O4.
  c.branch = c.first == s.b ? branch : (branch == Branch::Open ? Branch::Crossed : Branch::Open);
  return m;
}

Result<Mechanism> withCouplerPoint(const Mechanism& mechanism, const FourBarStructure& s,
                                   std::optional<CouplerPointSpec> spec) {
  Mechanism m = mechanism;
  const auto existing = couplerPointOf(m, s);
  if (!spec) {
    if (!existing) return m;
    const std::size_t gone = existing->id.index;
    m.points.erase(m.points.begin() + static_cast<std::ptrdiff_t>(gone));
    for (Link& l : m.links) {
      if (l.first.index > gone) --l.first.index;
      if (l.second.index > gone) --l.second.index;
    }
    return m;
  }
  if (existing) {
    auto& a = std::get<AttachedPoint>(m.points[existing->id.index].definition);
    const bool fromB = m.links[a.link.index].first == s.b;
    const CouplerPointSpec onLink = fromB ? *spec : flipped(*spec, s.lengths.coupler);
    a.along = onLink.along;
    a.across = onLink.across;
    return m;
  }
  const auto link = couplerLink(m, s);
  if (!link) return Error{ErrorCode::InvalidStructure, "couplerPoint", "this four-bar has no coupler link to carry P"};
  const bool fromB = m.links[link->index].first == s.b;
  const CouplerPointSpec onLink = fromB ? *spec : flipped(*spec, s.lengths.coupler);
  m.points.push_back({"P", AttachedPoint{*link, onLink.along, onLink.across}});
  return m;
}

}  // namespace linkwright::kinematics
