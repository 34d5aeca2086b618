#include "ui/panels/dimension_fields.h"

#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/model/units.h"

#include <QCoreApplication>

#include <type_traits>
#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("DimensionsPanel", text); }

QString nameOf(const k::Mechanism& m, k::PointId p) {
  return p.index < m.points.size() ? pointDisplayName(m.points[p.index].name) : QString();
}

// The address of a number, const or not as the mechanism it lies in.
template <typename Owner>
using NumberPtr = std::conditional_t<std::is_const_v<Owner>, const double*, double*>;

// Slots of a guide: 0 point x / along, 1 point y / across, 2 angle.
template <typename G>
NumberPtr<G> guideSlot(G& g, int slot) {
  switch (slot) {
  case 0: return &g.point.x();
  case 1: return &g.point.y();
  default: return &g.angle;
  }
}

void addGuideFields(std::vector<DimensionField>& out, const k::Mechanism& m, k::PointId p, const k::Guide& g, int base,
                    const QString& prefix) {
  if (g.link) {
    const QString link = QString::fromStdString(m.links[g.link->index].name);
    out.push_back({p, base, FieldKind::Offset, tr("%1 along %2").arg(prefix, link)});
    out.push_back({p, base + 1, FieldKind::Offset, tr("%1 across %2").arg(prefix, link)});
    out.push_back({p, base + 2, FieldKind::AngleDeg, tr("%1 angle to %2").arg(prefix, link)});
  } else {
    out.push_back({p, base, FieldKind::Offset, tr("%1 through x").arg(prefix)});
    out.push_back({p, base + 1, FieldKind::Offset, tr("%1 through y").arg(prefix)});
    out.push_back({p, base + 2, FieldKind::AngleDeg, tr("%1 angle").arg(prefix)});
  }
}

// The number behind (point, slot): one table for reading and writing.
template <typename M>
NumberPtr<M> slotOf(M& m, const DimensionField& f) {
  if (f.point.index >= m.points.size()) return nullptr;
  auto& definition = m.points[f.point.index].definition;
  if (auto* g = std::get_if<k::GroundPoint>(&definition)) return f.slot == 0 ? &g->position.x() : &g->position.y();
  if (auto* c = std::get_if<k::CrankPoint>(&definition)) return f.slot == 0 ? &c->length : &c->phase;
  if (auto* r = std::get_if<k::RrrPoint>(&definition)) return f.slot == 0 ? &r->firstLength : &r->secondLength;
  if (auto* s = std::get_if<k::RrpPoint>(&definition))
    return f.slot == 0 ? &s->length : guideSlot(s->guide, f.slot - 1);
  if (auto* s = std::get_if<k::RprPoint>(&definition)) return &s->length;
  if (auto* p = std::get_if<k::PrpPoint>(&definition))
    return f.slot < 3 ? guideSlot(p->first, f.slot) : guideSlot(p->second, f.slot - 3);
  if (auto* a = std::get_if<k::AttachedPoint>(&definition)) return f.slot == 0 ? &a->along : &a->across;
  if (auto* free = std::get_if<k::FreePoint>(&definition)) {
    if (f.slot < 2) return f.slot == 0 ? &free->guess.x() : &free->guess.y();
    const std::size_t c = static_cast<std::size_t>(f.slot - 2);
    return c < m.constraints.size() ? &m.constraints[c].length : nullptr;
  }
  return nullptr;
}

}  // namespace

std::vector<DimensionField> dimensionFields(const k::Mechanism& m) {
  std::vector<DimensionField> out;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const k::PointId p{i};
    const auto& definition = m.points[i].definition;
    const auto to = [&](k::PointId other) { return tr("to %1").arg(nameOf(m, other)); };
    if (std::holds_alternative<k::GroundPoint>(definition)) {
      out.push_back({p, 0, FieldKind::Offset, tr("x")});
      out.push_back({p, 1, FieldKind::Offset, tr("y")});
    } else if (const auto* c = std::get_if<k::CrankPoint>(&definition)) {
      out.push_back({p, 0, FieldKind::Length, to(c->pivot)});
      out.push_back({p, 1, FieldKind::AngleDeg, tr("phase")});
    } else if (const auto* r = std::get_if<k::RrrPoint>(&definition)) {
      out.push_back({p, 0, FieldKind::Length, to(r->first)});
      out.push_back({p, 1, FieldKind::Length, to(r->second)});
    } else if (const auto* s = std::get_if<k::RrpPoint>(&definition)) {
      out.push_back({p, 0, FieldKind::Length, to(s->first)});
      addGuideFields(out, m, p, s->guide, 1, tr("guide"));
    } else if (const auto* slot = std::get_if<k::RprPoint>(&definition)) {
      out.push_back({p, 0, FieldKind::Length, to(slot->pivot)});
    } else if (const auto* pin = std::get_if<k::PrpPoint>(&definition)) {
      addGuideFields(out, m, p, pin->first, 0, tr("guide 1"));
      addGuideFields(out, m, p, pin->second, 3, tr("guide 2"));
    } else if (std::holds_alternative<k::AttachedPoint>(definition)) {
      out.push_back({p, 0, FieldKind::Offset, tr("along")});
      out.push_back({p, 1, FieldKind::Offset, tr("across")});
    } else if (std::holds_alternative<k::FreePoint>(definition)) {
      out.push_back({p, 0, FieldKind::Offset, tr("guess x")});
      out.push_back({p, 1, FieldKind::Offset, tr("guess y")});
      // Each constraint is listed once, under the later of its two points.
      for (std::size_t ci = 0; ci < m.constraints.size(); ++ci) {
        const k::DistanceConstraint& dc = m.constraints[ci];
        if (std::max(dc.first.index, dc.second.index) != i) continue;
        out.push_back({p, static_cast<int>(2 + ci), FieldKind::Length, to(dc.first.index == i ? dc.second : dc.first)});
      }
    }
  }
  return out;
}

double fieldValue(const k::Mechanism& mechanism, const DimensionField& field) {
  const double* value = slotOf(mechanism, field);
  if (value == nullptr) return 0.0;
  return field.kind == FieldKind::AngleDeg ? k::radToDeg(*value) : *value;
}

void setFieldValue(k::Mechanism& mechanism, const DimensionField& field, double value) {
  if (double* slot = slotOf(mechanism, field)) *slot = field.kind == FieldKind::AngleDeg ? k::degToRad(value) : value;
}

k::Branch* branchOf(k::Point& point) {
  if (auto* r = std::get_if<k::RrrPoint>(&point.definition)) return &r->branch;
  if (auto* s = std::get_if<k::RrpPoint>(&point.definition)) return &s->branch;
  return nullptr;
}

const k::Branch* branchOf(const k::Point& point) {
  if (const auto* r = std::get_if<k::RrrPoint>(&point.definition)) return &r->branch;
  if (const auto* s = std::get_if<k::RrpPoint>(&point.definition)) return &s->branch;
  return nullptr;
}

QString pointRole(const k::Mechanism& m, k::PointId p) {
  const auto& d = m.points[p.index].definition;
  if (std::holds_alternative<k::GroundPoint>(d)) return tr("ground pivot");
  if (std::holds_alternative<k::CrankPoint>(d)) return tr("crank tip");
  if (std::holds_alternative<k::RrrPoint>(d)) return tr("joint of two links");
  if (std::holds_alternative<k::RrpPoint>(d)) return tr("slider");
  if (std::holds_alternative<k::RprPoint>(d)) return tr("slotted link's tip");
  if (std::holds_alternative<k::PrpPoint>(d)) return tr("pin of two sliders");
  if (const auto* a = std::get_if<k::AttachedPoint>(&d))
    return tr("on %1").arg(QString::fromStdString(m.links[a->link.index].name));
  return tr("free point");
}

}  // namespace linkwright::ui
