#include "kinematics/design/point_drag.h"

#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/guide_line.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

struct Dragger {
  Mechanism& m;
  const Pose& pose;
  double& input;  // the driver's coordinate, which dragging a driven point moves
  std::size_t index;
  const Eigen::Vector2d& target;

  // A length the drag would make (near) zero is refused: the point would sit on its parent.
  std::optional<Error> lengthTo(PointId parent, double& length) const {
    length = (target - pose.position[parent.index]).norm();
    if (length > 1e-9 * (1.0 + pose.position[parent.index].norm())) return std::nullopt;
    return Error{ErrorCode::InvalidValue, m.points[index].name,
                 m.points[index].name + " cannot be dropped onto " + m.points[parent.index].name +
                     ": the link between them would have no length"};
  }

  std::optional<Error> operator()(GroundPoint& g) const {
    g.position = target;
    return std::nullopt;
  }
  std::optional<Error> operator()(CrankPoint& c) const {
    if (auto e = lengthTo(c.pivot, c.length)) return e;
    const Eigen::Vector2d r = target - pose.position[c.pivot.index];
    c.phase = std::remainder(std::atan2(r.y(), r.x()) - input, 2.0 * std::acos(-1.0));
    return std::nullopt;
  }
  // The driven point slides along its path to the place nearest the pointer.
  std::optional<Error> operator()(PathPoint& d) const {
    input = nearestPathCoordinate(d.path, target);
    return std::nullopt;
  }
  // The actuator's end: its link takes the new length, the actuator the new stroke.
  std::optional<Error> operator()(ActuatorPoint& a) const {
    if (auto e = lengthTo(a.first, a.length)) return e;
    if (auto e = lengthTo(a.base, input)) return e;
    const double side = cross(target - pose.position[a.first.index], target - pose.position[a.base.index]);
    a.branch = side >= 0.0 ? Branch::Open : Branch::Crossed;
    return std::nullopt;
  }
  std::optional<Error> operator()(RrrPoint& r) const {
    if (auto e = lengthTo(r.first, r.firstLength)) return e;
    if (auto e = lengthTo(r.second, r.secondLength)) return e;
    const double side = cross(target - pose.position[r.first.index], target - pose.position[r.second.index]);
    r.branch = side >= 0.0 ? Branch::Open : Branch::Crossed;
    return std::nullopt;
  }
  std::optional<Error> operator()(RrpPoint& p) const {
    const GuideLine line = guideLineAt(m, p.guide, pose);
    const double s = line.direction.dot(target - line.point);
    const double foot = line.direction.dot(pose.position[p.first.index] - line.point);
    const Eigen::Vector2d onGuide = line.point + s * line.direction;
    p.length = (onGuide - pose.position[p.first.index]).norm();
    if (!(p.length > 0.0))
      return Error{ErrorCode::InvalidValue, m.points[index].name,
                   m.points[index].name + " cannot sit right under its rod's pin"};
    p.branch = s >= foot ? Branch::Open : Branch::Crossed;
    return std::nullopt;
  }
  std::optional<Error> operator()(RprPoint& s) const {
    const Eigen::Vector2d o = pose.position[s.pivot.index];
    const Eigen::Vector2d e = (pose.position[s.through.index] - o).normalized();
    s.length = e.dot(target - o);
    if (s.length > 0.0) return std::nullopt;
    return Error{ErrorCode::InvalidValue, m.points[index].name,
                 m.points[index].name + " must stay on the slot's side of " + m.points[s.through.index].name};
  }
  std::optional<Error> operator()(PrpPoint&) const {
    return Error{ErrorCode::InvalidValue, m.points[index].name,
                 m.points[index].name + " is where its two guides cross: move a guide instead"};
  }
  std::optional<Error> operator()(AttachedPoint& a) const {
    const Link& l = m.links[a.link.index];
    const Eigen::Vector2d base = pose.position[l.first.index];
    const Eigen::Vector2d u = (pose.position[l.second.index] - base).normalized();
    a.along = u.dot(target - base);
    a.across = perp(u).dot(target - base);
    return std::nullopt;
  }
  std::optional<Error> operator()(FreePoint& f) const {
    f.guess = target;
    for (DistanceConstraint& c : m.constraints) {
      if (c.first.index != index && c.second.index != index) continue;
      const PointId other = c.first.index == index ? c.second : c.first;
      if (auto e = lengthTo(other, c.length)) return e;
    }
    return std::nullopt;
  }
};

// The frame-line rule for a four-bar's pivots O2, O4 and its crank tip B.
std::optional<Error> dragOnFrameLine(const FourBarStructure& s, Mechanism& m, const Pose& pose, double& inputAngle,
                                     PointId point, const Eigen::Vector2d& target) {
  const Eigen::Vector2d o2 = pose.position[s.o2.index];
  const Eigen::Vector2d o4 = pose.position[s.o4.index];
  const Eigen::Vector2d along(std::cos(s.frameAngle), std::sin(s.frameAngle));
  const auto& name = [&m](PointId p) -> const std::string& { return m.points[p.index].name; };
  if (point == s.o2 || point == s.o4) {
    const Eigen::Vector2d onLine = o2 + along.dot(target - o2) * along;
    const double frame = point == s.o2 ? along.dot(o4 - onLine) : along.dot(onLine - o2);
    if (!(frame > 1e-9 * (1.0 + o2.norm() + o4.norm())))
      return Error{ErrorCode::InvalidValue, name(point),
                   name(point) + " cannot pass " + name(point == s.o2 ? s.o4 : s.o2) +
                       " on the frame line: the frame would have no length"};
    std::get<GroundPoint>(m.points[point.index].definition).position = onLine;
    return std::nullopt;
  }
  auto& crank = std::get<CrankPoint>(m.points[point.index].definition);
  const Eigen::Vector2d r = target - o2;
  if (!(r.norm() > 1e-9 * (1.0 + o2.norm())))
    return Error{
        ErrorCode::InvalidValue, name(point),
        name(point) + " cannot be dropped onto " + name(s.o2) + ": the link between them would have no length"};
  crank.length = r.norm();
  inputAngle = std::atan2(r.y(), r.x()) - crank.phase;
  return std::nullopt;
}

}  // namespace

Result<PointDrag> dragPoint(const Mechanism& mechanism, const Pose& pose, double inputAngle, PointId point,
                            const Eigen::Vector2d& target, DragRule rule) {
  if (point.index >= mechanism.points.size() || pose.position.size() != mechanism.points.size())
    return Error{ErrorCode::InvalidStructure, "point", "the dragged point does not belong to this linkage"};
  if (!target.allFinite()) return Error{ErrorCode::InvalidValue, "target", "the drag target must be a finite position"};
  PointDrag out{mechanism, inputAngle};
  Mechanism& m = out.mechanism;
  const auto fourBar = rule == DragRule::FrameLine ? asFourBar(mechanism) : std::nullopt;
  const bool framed = fourBar && (point == fourBar->o2 || point == fourBar->o4 || point == fourBar->b);
  if (auto e =
          framed ? dragOnFrameLine(*fourBar, m, pose, out.inputAngle, point, target)
                 : std::visit(Dragger{m, pose, out.inputAngle, point.index, target}, m.points[point.index].definition))
    return *e;
  if (auto e = checkMechanism(m)) return *e;
  return out;
}

Result<Mechanism> dragPathVertex(const Mechanism& mechanism, PointId point, std::size_t vertex,
                                 const Eigen::Vector2d& target) {
  const auto* driven = point.index < mechanism.points.size()
                           ? std::get_if<PathPoint>(&mechanism.points[point.index].definition)
                           : nullptr;
  const auto* line = driven != nullptr ? std::get_if<PolylinePath>(&driven->path) : nullptr;
  if (line == nullptr || vertex >= line->vertices.size())
    return Error{ErrorCode::InvalidStructure, "point", "the dragged path vertex does not belong to this linkage"};
  if (!target.allFinite()) return Error{ErrorCode::InvalidValue, "target", "the drag target must be a finite position"};
  Mechanism m = mechanism;
  auto& vertices = std::get<PolylinePath>(std::get<PathPoint>(m.points[point.index].definition).path).vertices;
  vertices[vertex] = target;
  const std::string& name = m.points[point.index].name;
  for (const std::size_t other : {vertex - 1, vertex + 1})
    if (other < vertices.size() && !((vertices[other] - target).norm() >= kMinLength))
      return Error{ErrorCode::InvalidValue, name,
                   "point " + std::to_string(vertex + 1) + " of " + name + "'s path cannot be dropped onto point " +
                       std::to_string(other + 1) + ": the segment between them would have no length"};
  if (auto e = checkMechanism(m)) return *e;
  return m;
}

}  // namespace linkwright::kinematics
