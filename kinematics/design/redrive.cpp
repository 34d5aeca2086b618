#include "kinematics/design/redrive.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/units.h"
#include "kinematics/model/vec2.h"
#include "kinematics/solve/pose_solver.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace linkwright::kinematics {
namespace {

using Eigen::Vector2d;

// A joint that can take over from `driver`: its parents, the length to the driver and the
// ground point (or ground guide) it is held to.
struct Successor {
  PointId ground;                ///< the ground pivot the new crank turns about (unused for a slider)
  double toDriver = 0.0;         ///< its length to the old driver
  double toGround = 0.0;         ///< its length to `ground`
  const Guide* guide = nullptr;  ///< a slider's ground guide
};

bool isGround(const Mechanism& m, PointId id) {
  return std::holds_alternative<GroundPoint>(m.points[id.index].definition);
}

// The straight path of a path driver (a polyline of one segment), if it is one.
const PolylinePath* straightPath(const PointDefinition& d) {
  const auto* path = std::get_if<PathPoint>(&d);
  if (path == nullptr) return nullptr;
  const auto* line = std::get_if<PolylinePath>(&path->path);
  return line != nullptr && line->vertices.size() == 2 ? line : nullptr;
}

// How point `c` can take over from `driver`, if it can (see redrive.h).
std::optional<Successor> successor(const Mechanism& m, PointId driver, PointId c) {
  const PointDefinition& d = m.points[driver.index].definition;
  const PointDefinition& def = m.points[c.index].definition;
  const bool crank = std::holds_alternative<CrankPoint>(d);
  if (!crank && straightPath(d) == nullptr) return std::nullopt;
  if (const auto* r = std::get_if<RrrPoint>(&def)) {
    if (r->first == driver && isGround(m, r->second)) return Successor{r->second, r->firstLength, r->secondLength};
    if (r->second == driver && isGround(m, r->first)) return Successor{r->first, r->secondLength, r->firstLength};
  }
  if (const auto* p = std::get_if<RrpPoint>(&def); crank && p != nullptr && p->first == driver && !p->guide.link)
    return Successor{PointId{}, p->length, 0.0, &p->guide};
  return std::nullopt;
}

std::string pointName(const Mechanism& m, PointId id) { return m.points[id.index].name; }

// "crank about O2": the link's name if a link joins the two points, else the point's.
std::string turningName(const Mechanism& m, PointId pivot, PointId tip) {
  for (const Link& link : m.links)
    if ((link.first == pivot && link.second == tip) || (link.first == tip && link.second == pivot))
      return link.name + " about " + pointName(m, pivot);
  return pointName(m, tip) + " about " + pointName(m, pivot);
}

std::string driverDescription(const Mechanism& m, PointId driver) {
  const PointDefinition& d = m.points[driver.index].definition;
  if (const auto* c = std::get_if<CrankPoint>(&d)) return turningName(m, c->pivot, driver) + " (angle)";
  if (std::holds_alternative<ActuatorPoint>(d)) return "actuator to " + pointName(m, driver) + " (length)";
  return pointName(m, driver) + " along its path (position)";
}

// Every point id in `d`, renamed by `map`.
void remap(PointDefinition& d, const std::vector<std::size_t>& map) {
  const auto re = [&](PointId& id) { id.index = map[id.index]; };
  std::visit(
      [&](auto& def) {
        using Def = std::decay_t<decltype(def)>;
        if constexpr (std::is_same_v<Def, CrankPoint>) re(def.pivot);
        else if constexpr (std::is_same_v<Def, ActuatorPoint>) {
          re(def.first);
          re(def.base);
        } else if constexpr (std::is_same_v<Def, RrrPoint>) {
          re(def.first);
          re(def.second);
        } else if constexpr (std::is_same_v<Def, RrpPoint>) re(def.first);
        else if constexpr (std::is_same_v<Def, RprPoint>) {
          re(def.pivot);
          re(def.through);
        }
      },
      d);
}

// `m` with `c` (and the ground pivot it needs) moved just before `b`, ids renamed to match:
// the new driver must be solved before the old one, which now hangs on it.
Mechanism reordered(Mechanism m, PointId b, PointId c, std::optional<PointId> ground) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < b.index; ++i)
    if (i != c.index) order.push_back(i);
  if (ground && ground->index > b.index) order.push_back(ground->index);
  order.push_back(c.index);
  for (std::size_t i = b.index; i < m.points.size(); ++i)
    if (i != c.index && !(ground && i == ground->index && i > b.index)) order.push_back(i);
  std::vector<std::size_t> map(order.size());
  for (std::size_t n = 0; n < order.size(); ++n) map[order[n]] = n;
  std::vector<Point> points;
  points.reserve(order.size());
  for (const std::size_t old : order) points.push_back(std::move(m.points[old]));
  for (Point& p : points) remap(p.definition, map);
  m.points = std::move(points);
  for (Link& link : m.links) {
    link.first.index = map[link.first.index];
    link.second.index = map[link.second.index];
  }
  for (DistanceConstraint& k : m.constraints) {
    k.first.index = map[k.first.index];
    k.second.index = map[k.second.index];
  }
  return m;
}

Branch rrrBranch(const Vector2d& joint, const Vector2d& first, const Vector2d& second) {
  return cross(joint - first, joint - second) > 0.0 ? Branch::Open : Branch::Crossed;
}

// The stroke of slider C on a line (point g, unit direction u) driven by a crank of length r
// about A through a rod of length l, as guide coordinates (lower, upper) on C's side of A:
// the dead centres when the crank turns fully, else C's reach either way of where it is.
std::pair<double, double> stroke(const Vector2d& a, double r, double l, const Vector2d& g, const Vector2d& u,
                                 double atC) {
  const Vector2d n(-u.y(), u.x());
  const double along = (a - g).dot(u);
  const double offset = std::abs((a - g).dot(n));
  const double side = atC >= along ? 1.0 : -1.0;
  if (l - r < offset) return {atC - r, atC + r};
  const double inner = along + side * std::sqrt((l - r) * (l - r) - offset * offset);
  const double outer = along + side * std::sqrt((l + r) * (l + r) - offset * offset);
  return {std::min(inner, outer), std::max(inner, outer)};
}

Error notAChoice(const Mechanism& m, PointId point) {
  const std::string name = point.index < m.points.size() ? m.points[point.index].name : std::to_string(point.index);
  return Error{ErrorCode::InvalidValue, "driver",
               "driver: the linkage cannot be driven from " + name +
                   " (it can be driven from a dyad joint next to "
                   "its crank, or from the crank next to a point on a straight path)"};
}

}  // namespace

std::vector<DriverChoice> driverChoices(const Mechanism& m) {
  const std::optional<PointId> driver = driverPoint(m);
  if (!driver) return {};
  std::vector<DriverChoice> choices{{*driver, driverDescription(m, *driver)}};
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointId c{i};
    const auto s = successor(m, *driver, c);
    if (!s) continue;
    choices.push_back({c, s->guide != nullptr ? pointName(m, c) + " along its guide (position)"
                                              : turningName(m, s->ground, c) + " (angle)"});
  }
  return choices;
}

Result<Redriven> driveFrom(const Design& design, PointId point, double input) {
  const Mechanism& m = design.mechanism;
  const std::optional<PointId> driver = driverPoint(m);
  if (!driver || point.index >= m.points.size()) return notAChoice(m, point);
  if (point == *driver) return Redriven{design, input};
  const auto s = successor(m, *driver, point);
  if (!s) return notAChoice(m, point);
  const Result<Pose> pose = solvePose(m, DriverState{input, 0.0, 0.0}, SolveRequest{false, false});
  if (!pose) {
    Error e = pose.error();
    e.field = "driver";
    return e;
  }
  const auto at = [&](PointId id) { return pose->position[id.index]; };
  const Vector2d b = at(*driver);
  const Vector2d c = at(point);

  Mechanism next = m;
  PointDefinition& oldDriver = next.points[driver->index].definition;
  PointDefinition& newDriver = next.points[point.index].definition;
  Design result = design;
  double newInput = 0.0;
  double oldLength = 0.0;  // the old crank's, or the new one's: what turns a rate into a speed
  std::optional<PointId> ground;
  if (const auto* crank = std::get_if<CrankPoint>(&oldDriver)) {
    const PointId pivot = crank->pivot;
    oldLength = crank->length;
    if (s->guide != nullptr) {
      const Vector2d u(std::cos(s->guide->angle), std::sin(s->guide->angle));
      const Vector2d g = s->guide->point;
      const auto [lower, upper] = stroke(at(pivot), crank->length, s->toDriver, g, u, (c - g).dot(u));
      newDriver = PathPoint{PolylinePath{{g + lower * u, g + upper * u}}};
      newInput = (c - g).dot(u) - lower;
      const double span = upper - lower;
      result.fromDeg = 0.01 * span;
      result.toDeg = 0.99 * span;
      result.samples = 201;
      result.omega = std::abs(design.omega) * oldLength;
    } else {
      ground = s->ground;
      newDriver = CrankPoint{s->ground, s->toGround, 0.0};
      newInput = std::atan2((c - at(s->ground)).y(), (c - at(s->ground)).x());
    }
    oldDriver = RrrPoint{pivot, oldLength, point, s->toDriver, rrrBranch(b, at(pivot), c)};
  } else {
    // A point on a straight path, and the RRR joint on it and a ground pivot takes over.
    const PolylinePath line = *straightPath(oldDriver);
    const Vector2d g = line.vertices[0];
    const Vector2d u = (line.vertices[1] - g).normalized();
    ground = s->ground;
    newDriver = CrankPoint{s->ground, s->toGround, 0.0};
    newInput = std::atan2((c - at(s->ground)).y(), (c - at(s->ground)).x());
    oldDriver = RrpPoint{point, s->toDriver, Guide{std::nullopt, g, std::atan2(u.y(), u.x())},
                         (b - c).dot(u) > 0.0 ? Branch::Open : Branch::Crossed};
    result.omega = std::abs(design.omega) / s->toGround;
  }
  if (std::holds_alternative<CrankPoint>(newDriver)) {
    newInput = std::fmod(newInput + 2.0 * kPi, 2.0 * kPi);  // atan2's (−π, π] into [0, 2π)
    result.fromDeg = 0.0;
    result.toDeg = 360.0;
    result.samples = samplesEveryHalfDegree(0.0, 360.0);
  }
  result.alpha = 0.0;
  result.time.reset();
  result.mechanism = reordered(std::move(next), *driver, point, ground);
  if (auto e = checkDesign(result)) return *e;
  return Redriven{std::move(result), newInput};
}

}  // namespace linkwright::kinematics
