#include "kinematics/model/mechanism_check.h"

#include "kinematics/model/constraint_form.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace linkwright::kinematics {
namespace {

Error structureError(const std::string& field, const std::string& why) {
  return Error{ErrorCode::InvalidStructure, field, field + " " + why};
}

std::string pointField(std::size_t index, const char* member) {
  return "points[" + std::to_string(index) + "]." + member;
}

// A point may only refer to points before it: that order is the solve order.
std::optional<Error> checkEarlier(PointId ref, std::size_t index, const char* member) {
  if (ref.index < index) return std::nullopt;
  return structureError(pointField(index, member),
                        "must refer to a point defined before it (got point " + std::to_string(ref.index) + ")");
}

// A guide on a link needs the link's ends solved first; its numbers must be finite.
std::optional<Error> checkGuide(const Mechanism& m, const Guide& g, std::size_t i, const std::string& member) {
  const std::string field = pointField(i, member.c_str());
  if (g.link) {
    if (g.link->index >= m.links.size()) return structureError(field + ".link", "refers to a link that does not exist");
    const Link& link = m.links[g.link->index];
    if (link.first.index >= i || link.second.index >= i)
      return structureError(field + ".link", "must be a link between points defined before it");
  }
  if (auto e = checkCoordinate(g.point.x(), field + ".x")) return e;
  if (auto e = checkCoordinate(g.point.y(), field + ".y")) return e;
  return checkCoordinate(g.angle, field + ".angle");
}

std::optional<Error> checkPoint(const Mechanism& m, std::size_t i) {
  const PointDefinition& def = m.points[i].definition;
  if (const auto* g = std::get_if<GroundPoint>(&def)) {
    if (auto e = checkCoordinate(g->position.x(), pointField(i, "x"))) return e;
    return checkCoordinate(g->position.y(), pointField(i, "y"));
  }
  if (const auto* c = std::get_if<CrankPoint>(&def)) {
    if (auto e = checkEarlier(c->pivot, i, "pivot")) return e;
    if (!std::holds_alternative<GroundPoint>(m.points[c->pivot.index].definition))
      return structureError(pointField(i, "pivot"), "must be a ground point");
    if (auto e = checkLength(c->length, pointField(i, "length"))) return e;
    return checkCoordinate(c->phase, pointField(i, "phase"));
  }
  if (const auto* d = std::get_if<PathPoint>(&def)) return checkPathShape(d->path, pointField(i, "path"));
  if (const auto* a = std::get_if<ActuatorPoint>(&def)) {
    if (auto e = checkEarlier(a->first, i, "first")) return e;
    if (auto e = checkEarlier(a->base, i, "base")) return e;
    if (a->first == a->base) return structureError(pointField(i, "base"), "must differ from its first point");
    return checkLength(a->length, pointField(i, "length"));
  }
  if (const auto* r = std::get_if<RrrPoint>(&def)) {
    if (auto e = checkEarlier(r->first, i, "first")) return e;
    if (auto e = checkEarlier(r->second, i, "second")) return e;
    if (r->first == r->second) return structureError(pointField(i, "second"), "must differ from its first point");
    if (auto e = checkLength(r->firstLength, pointField(i, "firstLength"))) return e;
    return checkLength(r->secondLength, pointField(i, "secondLength"));
  }
  if (const auto* p = std::get_if<RrpPoint>(&def)) {
    if (auto e = checkEarlier(p->first, i, "first")) return e;
    if (auto e = checkLength(p->length, pointField(i, "length"))) return e;
    return checkGuide(m, p->guide, i, "guide");
  }
  if (const auto* q = std::get_if<PrpPoint>(&def)) {
    if (auto e = checkGuide(m, q->first, i, "firstGuide")) return e;
    return checkGuide(m, q->second, i, "secondGuide");
  }
  if (const auto* s = std::get_if<RprPoint>(&def)) {
    if (auto e = checkEarlier(s->pivot, i, "pivot")) return e;
    if (auto e = checkEarlier(s->through, i, "through")) return e;
    if (s->pivot == s->through) return structureError(pointField(i, "through"), "must differ from its pivot");
    return checkLength(s->length, pointField(i, "length"));
  }
  if (const auto* f = std::get_if<FreePoint>(&def)) {
    if (auto e = checkCoordinate(f->guess.x(), pointField(i, "guess.x"))) return e;
    return checkCoordinate(f->guess.y(), pointField(i, "guess.y"));
  }
  const auto& a = std::get<AttachedPoint>(def);
  if (a.link.index >= m.links.size())
    return structureError(pointField(i, "link"), "refers to a link that does not exist");
  const Link& link = m.links[a.link.index];
  if (link.first.index >= i || link.second.index >= i)
    return structureError(pointField(i, "link"), "must be a link between points defined before it");
  if (auto e = checkCoordinate(a.along, pointField(i, "along"))) return e;
  return checkCoordinate(a.across, pointField(i, "across"));
}

// A link is rigid only if one end is defined at a fixed distance from the other.
bool isRigidPair(const Mechanism& m, PointId a, PointId b) {
  auto definesFrom = [&](PointId child, PointId parent) {
    const PointDefinition& def = m.points[child.index].definition;
    if (const auto* c = std::get_if<CrankPoint>(&def)) return c->pivot == parent;
    if (const auto* actuator = std::get_if<ActuatorPoint>(&def)) return actuator->first == parent;
    if (const auto* r = std::get_if<RrrPoint>(&def)) return r->first == parent || r->second == parent;
    if (const auto* p = std::get_if<RrpPoint>(&def)) return p->first == parent;
    if (const auto* s = std::get_if<RprPoint>(&def)) return s->pivot == parent;
    return false;
  };
  for (const DistanceConstraint& c : m.constraints)
    if ((c.first == a && c.second == b) || (c.first == b && c.second == a)) return true;
  return definesFrom(a, b) || definesFrom(b, a);
}

// Each constraint joins two existing, distinct points, has a positive length, and closes on a
// free point: its later point is free (an earlier free point would already be solved).
std::optional<Error> checkConstraint(const Mechanism& m, std::size_t k) {
  const DistanceConstraint& c = m.constraints[k];
  const std::string field = "constraints[" + std::to_string(k) + "]";
  if (c.first.index >= m.points.size() || c.second.index >= m.points.size())
    return structureError(field, "refers to a point that does not exist");
  if (c.first == c.second) return structureError(field, "joins point " + m.points[c.first.index].name + " to itself");
  if (!(std::isfinite(c.length) && c.length > 0.0))
    return Error{ErrorCode::InvalidValue, field + ".length",
                 field + ".length must be positive and finite (got " + formatNumber(c.length) + ")"};
  const PointId later = constraintLaterPoint(c);
  if (!isFreePoint(m, later))
    return structureError(field, "joins " + m.points[c.first.index].name + " and " + m.points[c.second.index].name +
                                     ", but the later of them, " + m.points[later.index].name +
                                     ", is not a free point: a distance constraint must close on a free point");
  return std::nullopt;
}

// A run of free points is solved as one group: 2 unknowns per point, so exactly 2 constraints
// per point, and each point held by at least two of them (one alone would let it swing).
std::optional<Error> checkFreeGroup(const Mechanism& m, std::size_t first, std::size_t last) {
  std::string names;
  for (std::size_t i = first; i < last; ++i) names += (i == first ? "" : ", ") + m.points[i].name;
  const std::string which =
      "free points " + names + " (points[" + std::to_string(first) + ".." + std::to_string(last - 1) + "])";
  const std::size_t points = last - first;
  if (points > kMaxFreeGroupPoints)
    return structureError("points[" + std::to_string(first) + "]",
                          "starts " + which + ": a group of consecutive free points may hold at most " +
                              std::to_string(kMaxFreeGroupPoints) + " (got " + std::to_string(points) + ")");
  std::size_t count = 0;
  std::vector<int> holds(points, 0);
  for (const DistanceConstraint& c : m.constraints) {
    const std::size_t later = constraintLaterPoint(c).index;
    if (later < first || later >= last) continue;
    ++count;
    for (const PointId p : {c.first, c.second})
      if (p.index >= first) ++holds[p.index - first];
  }
  if (count != 2 * points)
    return structureError("constraints", "must hold " + which + " with exactly " + std::to_string(2 * points) +
                                             " distance constraints, two per point (got " + std::to_string(count) +
                                             ")");
  for (std::size_t i = 0; i < points; ++i)
    if (holds[i] < 2)
      return structureError("points[" + std::to_string(first + i) + "]",
                            "(" + m.points[first + i].name + ") is held by " + std::to_string(holds[i]) +
                                " distance constraint(s) of its group; a free point needs at least two");
  return std::nullopt;
}

// One length or coordinate of a linkage, named for messages ("link coupler", "O4.x").
struct Dimension {
  double value = 0.0;
  std::string name;
};

// The name of the link joining a and b, if one does, else "a–b".
std::string lengthName(const Mechanism& m, PointId a, PointId b) {
  for (const Link& link : m.links)
    if ((link.first == a && link.second == b) || (link.first == b && link.second == a)) return "link " + link.name;
  return "the length " + m.points[a.index].name + "–" + m.points[b.index].name;
}

// A path's extent counts as a length (a driven point's travel), its vertices or centre as
// coordinates.
template <typename Coordinate>
void pathDimensions(const PathShape& shape, std::size_t i, const std::string& name, std::vector<Dimension>& lengths,
                    Coordinate coordinate) {
  if (const auto* line = std::get_if<PolylinePath>(&shape)) {
    for (const Eigen::Vector2d& v : line->vertices) {
      coordinate(v.x(), i, "path.x");
      coordinate(v.y(), i, "path.y");
    }
    return;
  }
  const auto& arc = std::get<ArcPath>(shape);
  lengths.push_back({arc.radius, name + " path radius"});
  coordinate(arc.centre.x(), i, "path.centre.x");
  coordinate(arc.centre.y(), i, "path.centre.y");
}

// Every length and every coordinate the mechanism's numbers hold.
void dimensionsOf(const Mechanism& m, std::vector<Dimension>& lengths, std::vector<Dimension>& coordinates) {
  const auto coordinate = [&](double v, std::size_t i, const char* member) {
    coordinates.push_back({std::abs(v), m.points[i].name + "." + member});
  };
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointId self{i};
    const PointDefinition& def = m.points[i].definition;
    if (const auto* g = std::get_if<GroundPoint>(&def)) {
      coordinate(g->position.x(), i, "x");
      coordinate(g->position.y(), i, "y");
    } else if (const auto* c = std::get_if<CrankPoint>(&def)) {
      lengths.push_back({c->length, lengthName(m, c->pivot, self)});
    } else if (const auto* actuator = std::get_if<ActuatorPoint>(&def)) {
      lengths.push_back({actuator->length, lengthName(m, actuator->first, self)});
    } else if (const auto* d = std::get_if<PathPoint>(&def)) {
      pathDimensions(d->path, i, m.points[i].name, lengths, coordinate);
    } else if (const auto* r = std::get_if<RrrPoint>(&def)) {
      lengths.push_back({r->firstLength, lengthName(m, r->first, self)});
      lengths.push_back({r->secondLength, lengthName(m, r->second, self)});
    } else if (const auto* p = std::get_if<RrpPoint>(&def)) {
      lengths.push_back({p->length, lengthName(m, p->first, self)});
      coordinate(p->guide.point.x(), i, "guide.x");
      coordinate(p->guide.point.y(), i, "guide.y");
    } else if (const auto* s = std::get_if<RprPoint>(&def)) {
      lengths.push_back({s->length, lengthName(m, s->pivot, self)});
    } else if (const auto* q = std::get_if<PrpPoint>(&def)) {
      for (const Guide* guide : {&q->first, &q->second}) {
        coordinate(guide->point.x(), i, "guide.x");
        coordinate(guide->point.y(), i, "guide.y");
      }
    } else if (const auto* a = std::get_if<AttachedPoint>(&def)) {
      coordinate(a->along, i, "along");
      coordinate(a->across, i, "across");
    } else if (const auto* f = std::get_if<FreePoint>(&def)) {
      coordinate(f->guess.x(), i, "guess.x");
      coordinate(f->guess.y(), i, "guess.y");
    }
  }
  for (const DistanceConstraint& c : m.constraints) lengths.push_back({c.length, lengthName(m, c.first, c.second)});
}

}  // namespace

std::optional<Error> checkLinkageScale(const Mechanism& m) {
  std::vector<Dimension> lengths, coordinates;
  dimensionsOf(m, lengths, coordinates);
  if (lengths.empty()) return std::nullopt;
  const auto byValue = [](const Dimension& a, const Dimension& b) { return a.value < b.value; };
  const Dimension& shortest = *std::min_element(lengths.begin(), lengths.end(), byValue);
  Dimension largest = *std::max_element(lengths.begin(), lengths.end(), byValue);
  if (!coordinates.empty()) {
    const Dimension& far = *std::max_element(coordinates.begin(), coordinates.end(), byValue);
    if (far.value > largest.value) largest = far;
  }
  return checkScale(shortest.value, shortest.name, largest.value, largest.name, m.lengthUnit);
}

std::optional<Error> checkMechanism(const Mechanism& m) {
  std::set<std::string> names;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (m.points[i].name.empty()) return structureError(pointField(i, "name"), "must not be empty");
    if (!names.insert(m.points[i].name).second)
      return structureError(pointField(i, "name"), "repeats the name '" + m.points[i].name + "'");
  }
  int drivers = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (auto e = checkPoint(m, i)) return e;
    drivers += isDriver(m.points[i].definition) ? 1 : 0;
  }
  if (drivers != 1)
    return structureError("points",
                          "must contain exactly one driver: a crank, a point on a path or a linear actuator (got " +
                              std::to_string(drivers) + ")");
  for (std::size_t k = 0; k < m.constraints.size(); ++k)
    if (auto e = checkConstraint(m, k)) return e;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if (!isFreePoint(m, PointId{i})) continue;
    const std::size_t last = freeGroupEnd(m, i);
    if (auto e = checkFreeGroup(m, i, last)) return e;
    i = last - 1;
  }
  // Links last: their rigidity check reads point definitions, validated above.
  for (std::size_t k = 0; k < m.links.size(); ++k) {
    const Link& link = m.links[k];
    const std::string field = "links[" + std::to_string(k) + "]";
    if (link.name.empty()) return structureError(field + ".name", "must not be empty");
    if (link.first.index >= m.points.size() || link.second.index >= m.points.size())
      return structureError(field, "refers to a point that does not exist");
    if (!isRigidPair(m, link.first, link.second))
      return structureError(field, "joins points that are not held at a fixed distance");
  }
  return checkLinkageScale(m);
}

}  // namespace linkwright::kinematics
