#include "kinematics/design/dyad_request.h"

#include "kinematics/model/units.h"
#include "kinematics/solve/guide_line.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {

namespace {

bool nameTaken(const Mechanism& m, const std::string& name) { return m.findPoint(name).has_value(); }

// Adds the parent if it is new and returns its id in the grown mechanism.
Result<PointId> resolveParent(Mechanism& m, const ParentChoice& parent) {
  using Source = ParentChoice::Source;
  if (parent.source == Source::Existing) {
    if (parent.point.index >= m.points.size())
      return Error{ErrorCode::InvalidStructure, "parent", "the chosen point does not belong to this linkage"};
    return parent.point;
  }
  const bool ground = parent.source == Source::NewGround;
  const std::string name = freshPointName(m, ground);
  auto grown = ground ? addGroundPivot(m, name, parent.position)
                      : addPointOnLink(m, name, parent.link, parent.along, parent.across);
  if (!grown) return grown.error();
  m = std::move(*grown);
  return PointId{m.points.size() - 1};
}

// The parents added and the dyad's spec, or why not.
struct Prepared {
  Mechanism mechanism;
  PointId first;
  PointId second;
};

Result<Prepared> prepare(const Mechanism& mechanism, const DyadRequest& r) {
  Prepared p{mechanism, {}, {}};
  if (r.kind != DyadKind::Prp) {
    const auto first = resolveParent(p.mechanism, r.first);
    if (!first) return first.error();
    p.first = *first;
  }
  if (r.kind == DyadKind::Rrr || r.kind == DyadKind::Rpr) {
    const auto second = resolveParent(p.mechanism, r.second);
    if (!second) return second.error();
    p.second = *second;
  }
  return p;
}

DyadSpec specOf(const DyadRequest& r, const Prepared& p) {
  switch (r.kind) {
  case DyadKind::Rrr: return RrrDyadSpec{r.joint, p.first, r.firstLength, p.second, r.secondLength, r.branch};
  case DyadKind::Rrp: return RrpDyadSpec{r.joint, p.first, r.firstLength, r.guide, r.branch};
  case DyadKind::Rpr: return RprDyadSpec{r.joint, p.first, p.second, r.firstLength};
  case DyadKind::Prp: return PrpDyadSpec{r.joint, r.guide, r.secondGuide};
  }
  return RrrDyadSpec{};
}

// The last point that moves, preferring points fixed on links (where a designer hangs a dyad).
PointId lastMoving(const Mechanism& m, bool preferAttached) {
  for (std::size_t i = m.points.size(); preferAttached && i-- > 0;)
    if (std::holds_alternative<AttachedPoint>(m.points[i].definition)) return {i};
  for (std::size_t i = m.points.size(); i-- > 0;)
    if (!std::holds_alternative<GroundPoint>(m.points[i].definition)) return {i};
  return {0};
}

std::optional<PointId> firstGround(const Mechanism& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (std::holds_alternative<GroundPoint>(m.points[i].definition)) return PointId{i};
  return std::nullopt;
}

}  // namespace

std::string freshPointName(const Mechanism& m, bool groundPivot) {
  if (groundPivot) {
    for (int n = 2;; ++n)
      if (const std::string name = "O" + std::to_string(n); !nameTaken(m, name)) return name;
  }
  for (char c = 'E'; c <= 'Z'; ++c)
    if (c != 'O' && !nameTaken(m, std::string(1, c))) return std::string(1, c);
  for (int n = 1;; ++n)
    if (const std::string name = "J" + std::to_string(n); !nameTaken(m, name)) return name;
}

Result<Mechanism> applyDyadRequest(const Mechanism& mechanism, const DyadRequest& r) {
  if (r.joint.empty()) return Error{ErrorCode::InvalidValue, "joint", "the new joint needs a name"};
  if (nameTaken(mechanism, r.joint))
    return Error{ErrorCode::InvalidValue, "joint", "there is already a point named " + r.joint};
  const auto prepared = prepare(mechanism, r);
  if (!prepared) return prepared.error();
  return attachDyad(prepared->mechanism, specOf(r, *prepared));
}

Result<Design> attachToDesign(const Design& design, const DyadRequest& r) {
  auto grown = applyDyadRequest(design.mechanism, r);
  if (!grown) return grown.error();
  // The links keep their names, so the masses and loads carry over.
  Design out = design;
  out.kind = "linkage";
  out.mechanism = std::move(*grown);
  return out;
}

void fillLengths(const Mechanism& mechanism, double crankAngle, DyadRequest& r) {
  if (r.kind == DyadKind::Prp) return;
  const auto prepared = prepare(mechanism, r);
  if (!prepared) return;
  const auto pose = solvePose(prepared->mechanism, {crankAngle, 0.0, 0.0}, {false, false});
  if (!pose) return;
  const Eigen::Vector2d a = pose->position[prepared->first.index];
  // The linkage's reach from the first parent: a length scale when distances say nothing.
  double span = 0.0;
  for (const Eigen::Vector2d& q : pose->position) span = std::max(span, (q - a).norm());
  if (!(span > 0.0)) span = 1.0;
  switch (r.kind) {
  case DyadKind::Rrr: {
    const double d = (pose->position[prepared->second.index] - a).norm();
    r.firstLength = r.secondLength = d > 1e-9 * span ? 0.75 * d : 0.5 * span;
    break;
  }
  case DyadKind::Rrp: {
    const GuideLine line = guideLineAt(prepared->mechanism, r.guide, *pose);
    const double offset = std::abs(guideNormal(line).dot(a - line.point));
    r.firstLength = std::max(1.25 * offset, 0.5 * span);
    break;
  }
  case DyadKind::Rpr: {
    const double d = (pose->position[prepared->second.index] - a).norm();
    r.firstLength = d > 1e-9 * span ? 1.25 * d : 0.5 * span;
    break;
  }
  case DyadKind::Prp: break;
  }
}

DyadRequest suggestDyad(const Mechanism& m, double crankAngle, DyadKind kind) {
  DyadRequest r;
  r.kind = kind;
  r.joint = freshPointName(m);
  const auto pose = solvePose(m, {crankAngle, 0.0, 0.0}, {false, false});
  const PointId moving = lastMoving(m, kind == DyadKind::Rrr);
  const Eigen::Vector2d at = pose ? pose->position[moving.index] : Eigen::Vector2d::Zero();
  const std::optional<PointId> ground = firstGround(m);
  const double groundY = pose && ground ? pose->position[ground->index].y() : 0.0;
  double span = 1.0;
  if (pose)
    for (const Eigen::Vector2d& q : pose->position) span = std::max(span, (q - at).norm());
  using Source = ParentChoice::Source;
  switch (kind) {
  case DyadKind::Rrr:
    r.first.source = Source::Existing;
    r.first.point = moving;
    r.second.source = Source::NewGround;
    r.second.position = Eigen::Vector2d(at.x() + 0.6 * span, groundY);
    break;
  case DyadKind::Rrp:
    r.first.source = Source::Existing;
    r.first.point = moving;
    r.guide = Guide{std::nullopt, Eigen::Vector2d(at.x(), groundY), 0.0};
    break;
  case DyadKind::Rpr:
    r.first.source = Source::NewGround;
    r.first.position = Eigen::Vector2d(at.x(), at.y() - 0.6 * span);
    r.second.source = Source::Existing;
    r.second.point = moving;
    break;
  case DyadKind::Prp:
    // A block sliding on the last link, pinned to a block in a vertical ground slot.
    r.guide = Guide{m.links.empty() ? std::nullopt : std::optional<LinkId>(LinkId{m.links.size() - 1}),
                    Eigen::Vector2d::Zero(), 0.0};
    r.secondGuide = Guide{std::nullopt, at, kPi / 2.0};
    break;
  }
  fillLengths(m, crankAngle, r);
  return r;
}

}  // namespace linkwright::kinematics
