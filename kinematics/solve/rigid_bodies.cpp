#include "kinematics/solve/rigid_bodies.h"

#include "kinematics/model/driver.h"
#include "kinematics/solve/guide_line.h"

#include <algorithm>
#include <array>
#include <iterator>

namespace linkwright::kinematics {
namespace {

// A body while merging: its points (sorted) and the bar it started from.
struct Cluster {
  std::vector<std::size_t> points;
  std::array<std::size_t, 2> bar{};
};

std::vector<std::size_t> shared(const Cluster& a, const Cluster& b) {
  std::vector<std::size_t> out;
  std::set_intersection(a.points.begin(), a.points.end(), b.points.begin(), b.points.end(), std::back_inserter(out));
  return out;
}

void absorb(std::vector<Cluster>& clusters, std::size_t into, std::size_t from) {
  std::vector<std::size_t> merged;
  std::set_union(clusters[into].points.begin(), clusters[into].points.end(), clusters[from].points.begin(),
                 clusters[from].points.end(), std::back_inserter(merged));
  clusters[into].points = std::move(merged);
  clusters.erase(clusters.begin() + static_cast<std::ptrdiff_t>(from));
}

// One merge, if any applies: two clusters sharing two points, or a triangle of three clusters
// pairwise sharing three distinct single points. The lower index absorbs, so the ground (0)
// stays first and the order of first definition is kept.
bool mergeOnce(std::vector<Cluster>& c) {
  for (std::size_t a = 0; a < c.size(); ++a)
    for (std::size_t b = a + 1; b < c.size(); ++b)
      if (shared(c[a], c[b]).size() >= 2) {
        absorb(c, a, b);
        return true;
      }
  for (std::size_t a = 0; a < c.size(); ++a)
    for (std::size_t b = a + 1; b < c.size(); ++b) {
      const auto ab = shared(c[a], c[b]);
      if (ab.size() != 1) continue;
      for (std::size_t d = b + 1; d < c.size(); ++d) {
        const auto bd = shared(c[b], c[d]);
        const auto ad = shared(c[a], c[d]);
        if (bd.size() != 1 || ad.size() != 1) continue;
        if (ab[0] == bd[0] || ab[0] == ad[0] || bd[0] == ad[0]) continue;
        absorb(c, b, d);
        absorb(c, a, b);
        return true;
      }
    }
  return false;
}

void addBar(std::vector<Cluster>& clusters, std::vector<std::size_t> points) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 2) return;
  clusters.push_back({points, {points[0], points[1]}});
}

// The ground and every bar the definitions, links and constraints imply (header comment).
std::vector<Cluster> barsOf(const Mechanism& m) {
  std::vector<Cluster> clusters(1);
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointDefinition& def = m.points[i].definition;
    if (std::holds_alternative<GroundPoint>(def)) clusters[0].points.push_back(i);
    else if (const auto* c = std::get_if<CrankPoint>(&def)) addBar(clusters, {c->pivot.index, i});
    else if (const auto* actuator = std::get_if<ActuatorPoint>(&def)) addBar(clusters, {actuator->first.index, i});
    else if (const auto* r = std::get_if<RrrPoint>(&def)) {
      addBar(clusters, {r->first.index, i});
      addBar(clusters, {r->second.index, i});
    } else if (const auto* p = std::get_if<RrpPoint>(&def)) addBar(clusters, {p->first.index, i});
    else if (const auto* s = std::get_if<RprPoint>(&def)) addBar(clusters, {s->pivot.index, i});
    else if (const auto* a = std::get_if<AttachedPoint>(&def)) {
      const Link& l = m.links[a->link.index];
      addBar(clusters, {l.first.index, l.second.index, i});
    }
  }
  for (const Link& l : m.links) addBar(clusters, {l.first.index, l.second.index});
  for (const DistanceConstraint& c : m.constraints) addBar(clusters, {c.first.index, c.second.index});
  while (mergeOnce(clusters)) {
  }
  return clusters;
}

std::optional<BodyId> bodyHolding(const BodyModel& model, PointId a, PointId b) {
  for (std::size_t k = 0; k < model.bodies.size(); ++k)
    if (model.bodies[k].kind != BodyKind::Slider && model.holds(BodyId{k}, a) && model.holds(BodyId{k}, b))
      return BodyId{k};
  return std::nullopt;
}

BodyId guideBody(const BodyModel& model, const Guide& guide) {
  return guide.link ? model.linkBody[guide.link->index] : kGroundBody;
}

void addBlock(BodyModel& model, const Mechanism& m, SliderKey key, PointId pin, BodyId guide,
              const std::string& suffix) {
  const BodyId block{model.bodies.size()};
  const std::string name = m.points[pin.index].name + suffix;
  Body body{BodyKind::Slider, "slider_" + name, {pin}, {}, pin, pin, key, guide};
  model.bodies.push_back(std::move(body));
  model.prismatics.push_back({name, key, pin, block, guide});
}

void addBlocks(BodyModel& model, const Mechanism& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const PointDefinition& def = m.points[i].definition;
    const PointId id{i};
    if (const auto* p = std::get_if<RrpPoint>(&def)) addBlock(model, m, {id, 0}, id, guideBody(model, p->guide), "");
    else if (const auto* s = std::get_if<RprPoint>(&def))
      addBlock(model, m, {id, 0}, s->through, *bodyHolding(model, s->pivot, id), "_" + m.points[i].name);
    else if (const auto* q = std::get_if<PrpPoint>(&def)) {
      addBlock(model, m, {id, 0}, id, guideBody(model, q->first), "_1");
      addBlock(model, m, {id, 1}, id, guideBody(model, q->second), "_2");
    }
  }
}

// k bodies at a point: k − 1 pins to the hub (the ground if it is there, else the lowest body).
void addRevolutes(BodyModel& model, const Mechanism& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    std::vector<BodyId> at;
    for (std::size_t k = 0; k < model.bodies.size(); ++k)
      if (model.holds(BodyId{k}, PointId{i})) at.push_back(BodyId{k});
    for (std::size_t k = 1; k < at.size(); ++k) {
      const std::string& point = m.points[i].name;
      const std::string name = at.size() > 2 ? point + "_" + model.bodies[at[k].index].name : point;
      model.revolutes.push_back({name, PointId{i}, at[0], at[k]});
    }
  }
}

void nameBodies(BodyModel& model, const Mechanism& m) {
  for (std::size_t k = 0; k < model.bodies.size(); ++k) {
    Body& b = model.bodies[k];
    if (b.kind == BodyKind::Ground) b.name = "ground";
    else if (b.kind == BodyKind::Rigid)
      b.name = b.links.empty() ? "body" + std::to_string(k) : m.links[b.links[0].index].name;
  }
}

std::string countText(const BodyModel& model) {
  const std::size_t joints = model.revolutes.size() + model.prismatics.size();
  std::string bodies;
  for (std::size_t k = 1; k < model.bodies.size(); ++k) bodies += (k == 1 ? "" : ", ") + model.bodies[k].name;
  return "Gruebler's count 3(n − 1) − 2j = 3·" + std::to_string(model.movingBodies()) + " − 2·" +
         std::to_string(joints) + " = " + std::to_string(model.mobility()) + " with " +
         std::to_string(model.movingBodies()) + " moving bodies (" + bodies + "), " +
         std::to_string(model.revolutes.size()) + " revolute and " + std::to_string(model.prismatics.size()) +
         " prismatic joints";
}

Error fixedError(const Mechanism& m, const std::string& what, PointId point) {
  return Error{ErrorCode::InvalidStructure, "points",
               "the " + what + " " + m.points[point.index].name +
                   " is fixed to the ground by the rest of the linkage: nothing can move"};
}

// The driver's generalized force acts on a body (header comment): the one that holds the
// crank, the actuator's link or the path point, and for an actuator the one at its base.
std::optional<Error> findDrive(BodyModel& model, const Mechanism& m) {
  const auto driver = driverPoint(m);
  if (!driver) return Error{ErrorCode::InvalidStructure, "points", "forces need a driver: this linkage has none"};
  Drive& d = model.drive;
  d.point = *driver;
  d.pivot = *driver;
  d.name = m.points[driver->index].name;
  const PointDefinition& def = m.points[driver->index].definition;
  if (const auto* c = std::get_if<CrankPoint>(&def)) {
    d.kind = DriveKind::Crank;
    d.pivot = c->pivot;
    const auto body = bodyHolding(model, c->pivot, *driver);
    if (!body || *body == kGroundBody) return fixedError(m, "crank", *driver);
    d.body = *body;
  } else if (const auto* a = std::get_if<ActuatorPoint>(&def)) {
    d.kind = DriveKind::Actuator;
    d.pivot = a->base;
    const auto body = bodyHolding(model, a->first, *driver);
    if (!body || *body == kGroundBody) return fixedError(m, "actuator's end", *driver);
    const auto base = model.hubOf(a->base);
    const std::string& name = m.points[driver->index].name;
    const std::string& baseName = m.points[a->base.index].name;
    if (!base)
      return Error{ErrorCode::InvalidStructure, "points",
                   "forces need the base " + baseName + " of the actuator to " + name +
                       " on a body (the ground or a link) to push from: it is on none"};
    if (*base == *body)
      return Error{ErrorCode::InvalidStructure, "points",
                   "the actuator's ends " + baseName + " and " + name +
                       " lie on one rigid body, so it cannot change length: nothing can move"};
    d.body = *body;
    d.base = *base;
  } else {
    d.kind = DriveKind::Path;
    const auto body = model.hubOf(*driver);
    const std::string& name = m.points[driver->index].name;
    if (!body)
      return Error{ErrorCode::InvalidStructure, "points",
                   "forces need the point " + name + " driven along the path to lie on a link: it is on none"};
    if (*body == kGroundBody) return fixedError(m, "point on the path", *driver);
    d.body = *body;
  }
  return std::nullopt;
}

// The RRR point whose parents are a ground pivot and the path driver's point, if any.
std::optional<SerialArm> serialArm(const BodyModel& model, const Mechanism& m) {
  if (model.drive.kind != DriveKind::Path) return std::nullopt;
  const PointId tip = model.drive.point;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const auto* r = std::get_if<RrrPoint>(&m.points[i].definition);
    if (!r) continue;
    for (const auto& [pivot, end] : {std::pair{r->first, r->second}, std::pair{r->second, r->first}})
      if (end == tip && model.holds(kGroundBody, pivot))
        return SerialArm{pivot, PointId{i}, m.points[pivot.index].name, m.points[i].name};
  }
  return std::nullopt;
}

std::optional<PointId> momentPoint(const BodyModel& model) {
  if (model.drive.kind == DriveKind::Crank) return model.drive.pivot;
  const auto& ground = model.bodies[kGroundBody.index].points;
  if (ground.empty()) return std::nullopt;
  return ground.front();
}

}  // namespace

int BodyModel::mobility() const {
  return 3 * static_cast<int>(movingBodies()) - 2 * static_cast<int>(revolutes.size() + prismatics.size());
}

std::optional<BodyId> BodyModel::findSlider(const SliderKey& key) const {
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].kind == BodyKind::Slider && bodies[k].slider == key) return BodyId{k};
  return std::nullopt;
}

std::optional<BodyId> BodyModel::hubOf(PointId point) const {
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (holds(BodyId{k}, point)) return BodyId{k};
  return std::nullopt;
}

bool BodyModel::holds(BodyId body, PointId point) const {
  const auto& p = bodies[body.index].points;
  return std::find(p.begin(), p.end(), point) != p.end();
}

Result<BodyModel> bodiesOf(const Mechanism& m) {
  BodyModel model;
  const std::vector<Cluster> clusters = barsOf(m);
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    Body b;
    b.kind = k == 0 ? BodyKind::Ground : BodyKind::Rigid;
    for (const std::size_t p : clusters[k].points) b.points.push_back(PointId{p});
    b.reference = PointId{clusters[k].bar[0]};
    b.second = PointId{clusters[k].bar[1]};
    model.bodies.push_back(std::move(b));
  }
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    const BodyId body = bodyHolding(model, m.links[l].first, m.links[l].second).value_or(kGroundBody);
    model.linkBody.push_back(body);
    Body& b = model.bodies[body.index];
    if (b.kind == BodyKind::Rigid && b.links.empty()) {
      b.reference = m.links[l].first;
      b.second = m.links[l].second;
    }
    b.links.push_back(LinkId{l});
  }
  nameBodies(model, m);
  addBlocks(model, m);
  addRevolutes(model, m);
  if (auto e = findDrive(model, m)) return *e;
  if (model.unknowns() != model.equations()) {
    const std::string need = model.drive.kind == DriveKind::Path
                                 ? "two degrees of freedom with its path point free (the path drive takes both)"
                                 : "one degree of freedom";
    return Error{ErrorCode::InvalidStructure, "mechanism",
                 "forces need a linkage with " + need + ": " + countText(model) + ", so inverse dynamics would have " +
                     std::to_string(model.unknowns()) + " unknowns for " + std::to_string(model.equations()) +
                     " equations"};
  }
  model.arm = serialArm(model, m);
  model.momentPoint = momentPoint(model);
  return model;
}

double linkLength(const Mechanism& m, LinkId id) {
  const Link& l = m.links[id.index];
  for (const DistanceConstraint& c : m.constraints)
    if ((c.first == l.first && c.second == l.second) || (c.first == l.second && c.second == l.first)) return c.length;
  for (const auto& [child, parent] : {std::pair{l.second, l.first}, std::pair{l.first, l.second}}) {
    const PointDefinition& def = m.points[child.index].definition;
    if (const auto* c = std::get_if<CrankPoint>(&def); c && c->pivot == parent) return c->length;
    if (const auto* a = std::get_if<ActuatorPoint>(&def); a && a->first == parent) return a->length;
    if (const auto* r = std::get_if<RrrPoint>(&def)) {
      if (r->first == parent) return r->firstLength;
      if (r->second == parent) return r->secondLength;
    }
    if (const auto* p = std::get_if<RrpPoint>(&def); p && p->first == parent) return p->length;
    if (const auto* s = std::get_if<RprPoint>(&def); s && s->pivot == parent) return s->length;
  }
  return 0.0;
}

Eigen::Vector2d prismaticDirection(const Mechanism& m, const PrismaticJoint& joint, const Pose& pose) {
  const PointDefinition& def = m.points[joint.slider.point.index].definition;
  if (const auto* p = std::get_if<RrpPoint>(&def)) return guideLineAt(m, p->guide, pose).direction;
  if (const auto* q = std::get_if<PrpPoint>(&def))
    return guideLineAt(m, joint.slider.guide == 0 ? q->first : q->second, pose).direction;
  const auto& s = std::get<RprPoint>(def);
  return (pose.position[joint.slider.point.index] - pose.position[s.pivot.index]).normalized();
}

}  // namespace linkwright::kinematics
