#include "ui/panels/dimension_fields.h"

#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/design/design_parameter.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"

#include <QCoreApplication>

#include <variant>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("DimensionsPanel", text); }

QString nameOf(const k::Mechanism& m, k::PointId p) {
  return p.index < m.points.size() ? pointDisplayName(m.points[p.index].name) : QString();
}

// The editor's label of a guide's number: through a point on a ground guide, or along and
// across a moving link for a guide fixed to it.
QString guideLabel(const k::Mechanism& m, const k::Guide& g, int which, const QString& prefix) {
  if (g.link) {
    const QString link = QString::fromStdString(m.links[g.link->index].name);
    if (which == 0) return tr("%1 along %2").arg(prefix, link);
    if (which == 1) return tr("%1 across %2").arg(prefix, link);
    return tr("%1 angle to %2").arg(prefix, link);
  }
  if (which == 0) return tr("%1 through x").arg(prefix);
  if (which == 1) return tr("%1 through y").arg(prefix);
  return tr("%1 angle").arg(prefix);
}

// A four-bar's named dimension: "Crank O2–B", by the linkage's own point names.
QString fourBarLabel(const k::Mechanism& m, const k::FourBarStructure& s, k::ParameterSlot slot) {
  using S = k::ParameterSlot;
  const auto between = [&](const char* text, k::PointId a, k::PointId b) {
    return tr(text).arg(nameOf(m, a), nameOf(m, b));
  };
  switch (slot) {
  case S::FrameLength: return between("Frame %1–%2", s.o2, s.o4);
  case S::CrankLength: return between("Crank %1–%2", s.o2, s.b);
  case S::CouplerLength: return between("Coupler %1–%2", s.b, s.c);
  case S::RockerLength: return between("Rocker %1–%2", s.o4, s.c);
  default: return between("frame angle %1→%2", s.o2, s.o4);
  }
}

// Along and across the link a point is fixed on, named by the link's ends.
QString offsetLabel(const k::Mechanism& m, const k::AttachedPoint& a, bool along) {
  const k::Link& link = m.links[a.link.index];
  return (along ? tr("along %1→%2") : tr("across, left of %1→%2")).arg(nameOf(m, link.first), nameOf(m, link.second));
}

QString labelOf(const k::Mechanism& m, const std::optional<k::FourBarStructure>& fourBar, const k::Parameter& p) {
  using S = k::ParameterSlot;
  if (fourBar && k::isFourBarDimension(p.slot)) return fourBarLabel(m, *fourBar, p.slot);
  const auto& d = m.points[p.point.index].definition;
  const auto to = [&](k::PointId other) { return tr("to %1").arg(nameOf(m, other)); };
  const bool free = std::holds_alternative<k::FreePoint>(d);
  const auto* driven = std::get_if<k::PathPoint>(&d);
  const bool onArc = driven != nullptr && std::holds_alternative<k::ArcPath>(driven->path);
  switch (p.slot) {
  case S::X: return free ? tr("guess x") : onArc ? tr("path centre x") : tr("x");
  case S::Y: return free ? tr("guess y") : onArc ? tr("path centre y") : tr("y");
  case S::Phase: return onArc ? tr("path start angle") : tr("phase");
  case S::Sweep: return tr("path sweep");
  case S::PathX: return tr("path point %1 x").arg(p.vertex + 1);
  case S::PathY: return tr("path point %1 y").arg(p.vertex + 1);
  case S::Along:
  case S::Across:
    if (const auto* a = std::get_if<k::AttachedPoint>(&d)) return offsetLabel(m, *a, p.slot == S::Along);
    return {};
  case S::Length:
    if (const auto* c = std::get_if<k::CrankPoint>(&d)) return to(c->pivot);
    if (const auto* r = std::get_if<k::RrrPoint>(&d)) return to(r->first);
    if (const auto* s = std::get_if<k::RrpPoint>(&d)) return to(s->first);
    if (const auto* s = std::get_if<k::RprPoint>(&d)) return to(s->pivot);
    if (const auto* a = std::get_if<k::ActuatorPoint>(&d)) return to(a->first);
    if (onArc) return tr("path radius");
    return {};
  case S::SecondLength: return to(std::get<k::RrrPoint>(d).second);
  case S::GuideX:
  case S::GuideY:
  case S::GuideAngle: {
    const int which = p.slot == S::GuideX ? 0 : p.slot == S::GuideY ? 1 : 2;
    if (const auto* s = std::get_if<k::RrpPoint>(&d)) return guideLabel(m, s->guide, which, tr("guide"));
    return guideLabel(m, std::get<k::PrpPoint>(d).first, which, tr("guide 1"));
  }
  case S::SecondGuideX:
  case S::SecondGuideY:
  case S::SecondGuideAngle: {
    const int which = p.slot == S::SecondGuideX ? 0 : p.slot == S::SecondGuideY ? 1 : 2;
    return guideLabel(m, std::get<k::PrpPoint>(d).second, which, tr("guide 2"));
  }
  case S::ConstraintLength: {
    const k::DistanceConstraint& dc = m.constraints[p.constraint];
    return to(dc.first == p.point ? dc.second : dc.first);
  }
  default: return {};
  }
  return {};
}

}  // namespace

std::vector<DimensionField> dimensionFields(const k::Mechanism& m) {
  return dimensionFields(m, k::asFourBar(m, k::PointsOnLinks::AnyLink));
}

std::vector<DimensionField> dimensionFields(const k::Mechanism& m, const std::optional<k::FourBarStructure>& fourBar) {
  std::vector<DimensionField> out;
  for (const k::Parameter& p : k::parametersOf(m, fourBar)) out.push_back({p, labelOf(m, fourBar, p)});
  return out;
}

std::vector<double> fieldValues(const k::Mechanism& mechanism, const std::vector<DimensionField>& fields,
                                const std::optional<k::FourBarStructure>& fourBar) {
  std::vector<k::Parameter> parameters;
  for (const DimensionField& f : fields) parameters.push_back(f.parameter);
  const std::vector<std::optional<double>> values = k::parameterValues(mechanism, parameters, fourBar);
  std::vector<double> out(fields.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    const double value = values[i].value_or(0.0);
    out[i] = fields[i].unit() == k::ParameterUnit::Angle ? k::radToDeg(value) : value;
  }
  return out;
}

void setFieldValue(k::Design& design, const DimensionField& field, double value) {
  k::setDesignParameter(design, field.parameter, field.unit() == k::ParameterUnit::Angle ? k::degToRad(value) : value);
}

k::Branch* branchOf(k::Point& point) {
  if (auto* r = std::get_if<k::RrrPoint>(&point.definition)) return &r->branch;
  if (auto* s = std::get_if<k::RrpPoint>(&point.definition)) return &s->branch;
  if (auto* a = std::get_if<k::ActuatorPoint>(&point.definition)) return &a->branch;
  return nullptr;
}

const k::Branch* branchOf(const k::Point& point) {
  if (const auto* r = std::get_if<k::RrrPoint>(&point.definition)) return &r->branch;
  if (const auto* s = std::get_if<k::RrpPoint>(&point.definition)) return &s->branch;
  if (const auto* a = std::get_if<k::ActuatorPoint>(&point.definition)) return &a->branch;
  return nullptr;
}

QString pointRole(const k::Mechanism& m, k::PointId p) {
  const auto& d = m.points[p.index].definition;
  if (std::holds_alternative<k::GroundPoint>(d)) return tr("ground pivot");
  if (std::holds_alternative<k::CrankPoint>(d)) return tr("crank tip");
  if (std::holds_alternative<k::PathPoint>(d)) return tr("driven along a path");
  if (std::holds_alternative<k::ActuatorPoint>(d)) return tr("end of a linear actuator");
  if (std::holds_alternative<k::RrrPoint>(d)) return tr("joint of two links");
  if (std::holds_alternative<k::RrpPoint>(d)) return tr("slider");
  if (std::holds_alternative<k::RprPoint>(d)) return tr("slotted link's tip");
  if (std::holds_alternative<k::PrpPoint>(d)) return tr("pin of two sliders");
  if (const auto* a = std::get_if<k::AttachedPoint>(&d))
    return tr("on %1").arg(QString::fromStdString(m.links[a->link.index].name));
  return tr("free point");
}

}  // namespace linkwright::ui
