#include "ui/canvas/mechanism_drawing.h"

#include <algorithm>
#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

void join(DrawingPlan& plan, k::PointId a, k::PointId b) {
  auto& na = plan.neighbours[a.index];
  auto& nb = plan.neighbours[b.index];
  if (std::find(na.begin(), na.end(), b) == na.end()) na.push_back(b);
  if (std::find(nb.begin(), nb.end(), a) == nb.end()) nb.push_back(a);
}

bool linkJoins(const k::Mechanism& m, k::PointId a, k::PointId b) {
  return std::any_of(m.links.begin(), m.links.end(), [&](const k::Link& l) {
    return (l.first == a && l.second == b) || (l.first == b && l.second == a);
  });
}

}  // namespace

DrawingPlan planDrawing(const k::Mechanism& m) {
  DrawingPlan plan;
  const std::size_t n = m.points.size();
  plan.barLinks.assign(m.links.size(), true);
  plan.ground.assign(n, false);
  plan.draggable.assign(n, true);
  plan.traced.assign(n, false);
  plan.attached.assign(n, false);
  plan.neighbours.assign(n, {});
  std::vector<std::vector<k::PointId>> attachedTo(m.links.size());
  std::size_t sliders = 0;
  std::vector<k::PointId> groundPoints;
  for (std::size_t i = 0; i < n; ++i) {
    const k::PointId id{i};
    const auto& definition = m.points[i].definition;
    if (std::holds_alternative<k::GroundPoint>(definition)) {
      plan.ground[i] = true;
      groundPoints.push_back(id);
    } else if (const auto* a = std::get_if<k::AttachedPoint>(&definition)) {
      plan.attached[i] = true;
      plan.traced[i] = true;  // a point on a link traces the curve a designer looks for
      if (a->link.index < attachedTo.size()) attachedTo[a->link.index].push_back(id);
    } else if (const auto* s = std::get_if<k::RrpPoint>(&definition)) {
      plan.sliders.push_back({id, 0, sliders++, !s->guide.link.has_value()});
    } else if (const auto* driven = std::get_if<k::PathPoint>(&definition)) {
      plan.drivenPaths.push_back(id);
      const auto* line = std::get_if<k::PolylinePath>(&driven->path);
      plan.pathVertices.push_back(line != nullptr ? line->vertices.size() : 0);
    } else if (const auto* actuator = std::get_if<k::ActuatorPoint>(&definition)) {
      plan.actuators.push_back({actuator->base, id});
      join(plan, actuator->base, id);
    } else if (const auto* r = std::get_if<k::RrrPoint>(&definition)) {
      const auto isGround = [&](k::PointId q) {
        return std::holds_alternative<k::GroundPoint>(m.points[q.index].definition);
      };
      const auto isDriven = [&](k::PointId q) {
        return std::holds_alternative<k::PathPoint>(m.points[q.index].definition);
      };
      if (isGround(r->first) && isDriven(r->second)) plan.workspaces.push_back({r->first, id, r->second});
      if (isDriven(r->first) && isGround(r->second)) plan.workspaces.push_back({r->second, id, r->first});
    } else if (const auto* p = std::get_if<k::PrpPoint>(&definition)) {
      plan.draggable[i] = false;  // the guides fix it (point_drag.h)
      plan.sliders.push_back({id, 0, sliders, !p->first.link.has_value()});
      plan.sliders.push_back({id, 1, sliders++, !p->second.link.has_value()});
    }
  }
  for (std::size_t l = 0; l < m.links.size(); ++l) {
    const k::Link& link = m.links[l];
    join(plan, link.first, link.second);
    // The RPR link runs from its pivot to its tip; the slot passes through the block at `through`.
    if (const auto* rpr = std::get_if<k::RprPoint>(&m.points[link.second.index].definition);
        rpr != nullptr && rpr->pivot == link.first) {
      plan.barLinks[l] = false;
      plan.slottedLinks.push_back({k::LinkId{l}, link.first, rpr->through, link.second});
      join(plan, link.second, rpr->through);
    }
    if (attachedTo[l].empty()) continue;
    BodyShape body{k::LinkId{l}, {link.first, link.second}};
    for (const k::PointId p : attachedTo[l]) {
      body.corners.push_back(p);
      join(plan, link.first, p);
      join(plan, link.second, p);
    }
    plan.bodies.push_back(std::move(body));
  }
  for (std::size_t g = 1; g < groundPoints.size(); ++g)
    plan.frameLines.push_back({groundPoints[g - 1], groundPoints[g]});
  for (const k::DistanceConstraint& c : m.constraints) {
    join(plan, c.first, c.second);
    if (!linkJoins(m, c.first, c.second)) plan.constraintBars.push_back({c.first, c.second});
  }
  return plan;
}

const k::Guide& sliderGuide(const k::Mechanism& m, const SliderShape& slider) {
  const auto& definition = m.points[slider.joint.index].definition;
  if (const auto* p = std::get_if<k::PrpPoint>(&definition)) return slider.guide == 0 ? p->first : p->second;
  return std::get<k::RrpPoint>(definition).guide;
}

const k::CrankPoint* crankOf(const k::Mechanism& m) {
  for (const k::Point& p : m.points)
    if (const auto* c = std::get_if<k::CrankPoint>(&p.definition)) return c;
  return nullptr;
}

QString pointDisplayName(const std::string& name) {
  const QString text = QString::fromStdString(name);
  qsizetype digits = 0;
  while (digits < text.size() && text[text.size() - 1 - digits].isDigit()) ++digits;
  if (digits == 0 || digits == text.size() || !text[text.size() - 1 - digits].isUpper()) return text;
  QString out = text.left(text.size() - digits);
  for (qsizetype i = text.size() - digits; i < text.size(); ++i)
    out += QChar(0x2080 + text[i].digitValue());  // SUBSCRIPT ZERO onwards
  return out;
}

}  // namespace linkwright::ui
