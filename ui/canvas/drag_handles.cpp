#include "ui/canvas/drag_handles.h"

#include "ui/document/edit_design_command.h"

#include <QCoreApplication>

namespace linkwright::ui {

namespace k = kinematics;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("LinkageView", text); }

// What dragging a point of any linkage changes (point_drag.h), by how it is defined.
struct HintOf {
  QString name;
  QString operator()(const k::GroundPoint&) const { return tr("Drag %1 to move this ground pivot").arg(name); }
  QString operator()(const k::CrankPoint&) const {
    return tr("Drag %1 to change the crank length and phase").arg(name);
  }
  QString operator()(const k::PathPoint&) const { return tr("Drag %1 along its path to move the input").arg(name); }
  QString operator()(const k::ActuatorPoint&) const {
    return tr("Drag %1 to change its link's length and the actuator's stroke").arg(name);
  }
  QString operator()(const k::RrrPoint&) const {
    return tr("Drag %1 to change the lengths of the two links it joins").arg(name);
  }
  QString operator()(const k::RrpPoint&) const {
    return tr("Drag %1 along its guide to change the rod length").arg(name);
  }
  QString operator()(const k::RprPoint&) const { return tr("Drag %1 to change the slotted link's length").arg(name); }
  QString operator()(const k::PrpPoint&) const { return {}; }
  QString operator()(const k::AttachedPoint&) const { return tr("Drag %1 to move it on its link").arg(name); }
  QString operator()(const k::FreePoint&) const { return tr("Drag %1 to change the lengths that hold it").arg(name); }
};

// A four-bar's frame-line drags (point_drag.h, DragRule::FrameLine), by the point's role.
QString fourBarHint(const k::FourBarStructure& s, const k::Mechanism& m, k::PointId point) {
  const QString name = dragPointName(m, point);
  if (point == s.o2 || point == s.o4) return tr("Drag %1 along the frame line to change the frame length").arg(name);
  if (point == s.b) return tr("Drag %1 to change the crank length and angle").arg(name);
  if (point == s.c) return tr("Drag %1 to change the coupler and rocker lengths").arg(name);
  return tr("Drag %1 to move the coupler point on the coupler").arg(name);
}

}  // namespace

std::vector<DragHandle> dragHandles(const DrawingPlan& plan, const k::Mechanism& m) {
  std::vector<DragHandle> handles;
  const std::size_t n = plan.draggable.size();
  const auto add = [&](std::size_t i) { handles.push_back({k::PointId{i}, std::nullopt}); };
  // Later points sit on top of earlier ones in the drawing, so they are picked first.
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && plan.attached[i]) add(i);
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && !plan.attached[i] && !plan.ground[i]) add(i);
  // A driven point usually sits on its path's first vertex at the start: the point wins.
  for (const k::PointId p : plan.drivenPaths) {
    const auto& path = std::get<k::PathPoint>(m.points[p.index].definition).path;
    if (const auto* line = std::get_if<k::PolylinePath>(&path))
      for (std::size_t v = 0; v < line->vertices.size(); ++v) handles.push_back({p, v});
  }
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && plan.ground[i]) add(i);
  return handles;
}

QString dragPointName(const k::Mechanism& mechanism, k::PointId point) {
  return point.index < mechanism.points.size() ? pointDisplayName(mechanism.points[point.index].name) : QString();
}

QString dragHandleName(const k::Mechanism& mechanism, const DragHandle& handle) {
  const QString point = dragPointName(mechanism, handle.point);
  if (!handle.pathVertex) return point;
  return tr("%1 path point %2").arg(point).arg(*handle.pathVertex + 1);
}

QString dragHint(const std::optional<k::FourBarStructure>& fourBar, const k::Mechanism& mechanism,
                 const DragHandle& handle) {
  const k::PointId point = handle.point;
  if (point.index >= mechanism.points.size()) return {};
  if (handle.pathVertex)
    return tr("Drag to move point %1 of the path %2 is driven along")
        .arg(*handle.pathVertex + 1)
        .arg(dragPointName(mechanism, point));
  if (fourBar) return fourBarHint(*fourBar, mechanism, point);
  return std::visit(HintOf{dragPointName(mechanism, point)}, mechanism.points[point.index].definition);
}

}  // namespace linkwright::ui
