#include "kinematics/analysis/centre_model.h"

#include "kinematics/analysis/kennedy.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/vec2.h"

#include <algorithm>

namespace linkwright::kinematics {
namespace {

// Body numbers by BodyModel index (the header's numbering): the frame 1, the rigid bodies in
// definition order, each followed by the blocks pinned to it; blocks pinned to none last.
std::vector<std::size_t> numberBodies(const BodyModel& bodies) {
  const std::size_t count = bodies.bodies.size();
  std::vector<std::size_t> number(count, 0);
  number[0] = 1;
  std::size_t next = 2;
  for (std::size_t k = 1; k < count; ++k) {
    if (bodies.bodies[k].kind != BodyKind::Rigid) continue;
    number[k] = next++;
    for (std::size_t b = 1; b < count; ++b)
      if (bodies.bodies[b].kind == BodyKind::Slider && number[b] == 0 &&
          bodies.holds(BodyId{k}, bodies.bodies[b].reference))
        number[b] = next++;
  }
  for (std::size_t b = 1; b < count; ++b)
    if (number[b] == 0) number[b] = next++;
  return number;
}

std::string bodyName(const Mechanism& m, const Body& body) {
  if (body.kind == BodyKind::Ground) return "frame";
  if (body.kind == BodyKind::Rigid) return body.name;
  const std::string pin = m.points[body.reference.index].name;
  const bool twoGuides = std::holds_alternative<PrpPoint>(m.points[body.slider.point.index].definition);
  const std::string guide = twoGuides ? " (guide " + std::to_string(body.slider.guide + 1) + ")" : "";
  return (body.turnsWith == kGroundBody ? "slider " : "block ") + pin + guide;
}

void addJoint(CentreModel& model, CentreJoint joint) {
  if (joint.i > joint.j) std::swap(joint.i, joint.j);
  const bool seen = std::any_of(model.joints.begin(), model.joints.end(),
                                [&](const CentreJoint& j) { return j.i == joint.i && j.j == joint.j; });
  if (!seen) model.joints.push_back(std::move(joint));
}

// Pins where bodies share a point, slides where a block runs on its guide body; and each
// body's joints (the points it shares), which set the tolerances' scale.
void addJoints(CentreModel& model, const Mechanism& m, const BodyModel& bodies,
               const std::vector<std::size_t>& number) {
  model.bodyJoints.resize(bodies.bodies.size());
  for (std::size_t p = 0; p < m.points.size(); ++p) {
    std::vector<std::size_t> at;
    for (std::size_t k = 0; k < bodies.bodies.size(); ++k)
      if (bodies.holds(BodyId{k}, PointId{p})) at.push_back(k);
    if (at.size() < 2) continue;
    for (std::size_t a = 0; a < at.size(); ++a) {
      model.bodyJoints[number[at[a]] - 1].push_back(PointId{p});
      for (std::size_t b = a + 1; b < at.size(); ++b)
        addJoint(model, {number[at[a]], number[at[b]], CentreRule::Pin, PointId{p}, std::nullopt});
    }
  }
  for (const PrismaticJoint& s : bodies.prismatics)
    addJoint(model, {number[s.block.index], number[s.guide.index], CentreRule::Slide, s.pin, s});
}

const CentreJoint* frameJoint(const CentreModel& model, std::size_t body) {
  for (const CentreJoint& j : model.joints)
    if (j.i == 1 && j.j == body) return &j;
  return nullptr;
}

void findRatioBodies(CentreModel& model, const BodyModel& bodies, const std::vector<std::size_t>& number) {
  const Drive& drive = bodies.drive;
  if (drive.kind != DriveKind::Crank || !bodies.holds(kGroundBody, drive.pivot)) return;
  const std::size_t input = number[drive.body.index];
  for (std::size_t body = model.bodies.size(); body >= 2; --body) {
    const CentreJoint* joint = body == input ? nullptr : frameJoint(model, body);
    if (!joint) continue;
    model.ratio = {input, body, joint->rule == CentreRule::Slide};
    if (joint->rule == CentreRule::Slide) model.outputGuide = joint->slide;
    for (std::size_t k = 0; k < number.size(); ++k)
      if (number[k] == body && !bodies.bodies[k].links.empty()) model.outputLink = bodies.bodies[k].links.front();
    return;
  }
}

void findCentrodeBody(CentreModel& model, const BodyModel& bodies, const std::vector<std::size_t>& number) {
  for (std::size_t k = 1; k < bodies.bodies.size(); ++k) {
    const Body& body = bodies.bodies[k];
    if (body.kind != BodyKind::Rigid || frameJoint(model, number[k])) continue;
    if (model.centrodeBody != 0 && model.centrodeBody < number[k]) continue;
    model.centrodeBody = number[k];
    model.centrodeFirst = body.reference;
    model.centrodeSecond = body.second;
  }
}

}  // namespace

Result<CentreModel> centreModel(const Mechanism& m) {
  if (auto e = checkMechanism(m)) return *e;
  const auto bodies = bodiesOf(m);
  if (!bodies)
    return Error{ErrorCode::InvalidStructure, "mechanism",
                 "instant centres need the linkage's rigid bodies: " + bodies.error().message};
  const std::vector<std::size_t> number = numberBodies(*bodies);
  CentreModel model;
  model.bodies.resize(bodies->bodies.size());
  model.bodyIds.resize(bodies->bodies.size());
  for (std::size_t k = 0; k < bodies->bodies.size(); ++k) {
    model.bodies[number[k] - 1] = bodyName(m, bodies->bodies[k]);
    model.bodyIds[number[k] - 1] = BodyId{k};
  }
  for (const BodyId body : bodies->linkBody) model.linkNumbers.push_back(number[body.index]);
  addJoints(model, m, *bodies, number);
  findRatioBodies(model, *bodies, number);
  findCentrodeBody(model, *bodies, number);
  if (model.ratio.input != 0) model.anchor = bodies->drive.pivot;
  else if (!model.bodyJoints[0].empty()) model.anchor = model.bodyJoints[0].front();
  return model;
}

InstantCentres instantCentres(const Mechanism& m, const CentreModel& model, const Pose& pose) {
  InstantCentres c;
  instantCentresInto(m, model, pose, c);
  return c;
}

void instantCentresInto(const Mechanism& m, const CentreModel& model, const Pose& pose, InstantCentres& c) {
  const auto at = [&pose](PointId p) -> const Eigen::Vector2d& { return pose.position[p.index]; };
  if (c.bodies != model.bodies) c.bodies = model.bodies;
  const std::size_t n = c.bodyCount();
  c.centres.assign(n * (n - 1) / 2, InstantCentre{});
  c.origins.assign(c.centres.size(), CentreOrigin{});
  c.scale = 0.0;
  c.anchor = c.outputDirection = Eigen::Vector2d::Zero();
  for (const auto& joints : model.bodyJoints)
    for (std::size_t a = 0; a < joints.size(); ++a)
      for (std::size_t b = a + 1; b < joints.size(); ++b)
        c.scale = std::max(c.scale, (at(joints[b]) - at(joints[a])).norm());
  for (const CentreJoint& j : model.joints) {
    const std::size_t pair = c.pairIndex(j.i, j.j);
    c.origins[pair] = {j.rule, m.points[j.pin.index].name, at(j.pin), {}};
    c.centres[pair] = j.rule == CentreRule::Pin ? InstantCentre{CentreKind::Finite, at(j.pin), Eigen::Vector2d::Zero()}
                                                : centreAtInfinity(perp(prismaticDirection(m, *j.slide, pose)));
  }
  c.ratio = model.ratio;
  if (model.outputGuide) c.outputDirection = prismaticDirection(m, *model.outputGuide, pose);
  if (model.anchor) c.anchor = at(*model.anchor);
  completeByKennedy(c);
}

std::vector<std::size_t> linkNumbers(const Mechanism& m) {
  if (auto model = centreModel(m)) return model->linkNumbers;
  std::vector<std::size_t> out;
  for (std::size_t l = 0; l < m.links.size(); ++l) out.push_back(l + 2);
  return out;
}

}  // namespace linkwright::kinematics
