#include "ui/canvas/drag_handles.h"

#include "ui/document/edit_design_command.h"

#include "kinematics/model/fourbar.h"

#include <QCoreApplication>

namespace linkwright::ui {

namespace k = kinematics;
using kinematics::FourBarHandle;
namespace fourbar = kinematics::fourbar;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("LinkageView", text); }

// What dragging a point of any linkage changes (point_drag.h), by how it is defined.
struct HintOf {
  QString name;
  QString operator()(const k::GroundPoint&) const { return tr("Drag %1 to move this ground pivot").arg(name); }
  QString operator()(const k::CrankPoint&) const {
    return tr("Drag %1 to change the crank length and phase").arg(name);
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

}  // namespace

k::PointId handlePoint(FourBarHandle handle) {
  switch (handle) {
  case FourBarHandle::O2: return fourbar::kO2;
  case FourBarHandle::O4: return fourbar::kO4;
  case FourBarHandle::B: return fourbar::kB;
  case FourBarHandle::C: return fourbar::kC;
  case FourBarHandle::CouplerPoint: return fourbar::kCouplerPoint;
  }
  return fourbar::kO2;
}

std::optional<FourBarHandle> fourBarHandleOn(k::PointId point) {
  for (const FourBarHandle h :
       {FourBarHandle::O2, FourBarHandle::O4, FourBarHandle::B, FourBarHandle::C, FourBarHandle::CouplerPoint})
    if (handlePoint(h) == point) return h;
  return std::nullopt;
}

QString handleHint(FourBarHandle handle) {
  switch (handle) {
  case FourBarHandle::O2: return tr("Drag O\u2082 along the frame line to change the frame length");
  case FourBarHandle::O4: return tr("Drag O\u2084 along the frame line to change the frame length");
  case FourBarHandle::B: return tr("Drag B to change the crank length and angle");
  case FourBarHandle::C: return tr("Drag C to change the coupler and rocker lengths");
  case FourBarHandle::CouplerPoint: return tr("Drag P to move the coupler point on the coupler");
  }
  return {};
}

std::vector<k::PointId> draggablePoints(const DrawingPlan& plan) {
  std::vector<k::PointId> points;
  const std::size_t n = plan.draggable.size();
  // Later points sit on top of earlier ones in the drawing, so they are picked first.
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && plan.attached[i]) points.push_back({i});
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && !plan.attached[i] && !plan.ground[i]) points.push_back({i});
  for (std::size_t i = n; i-- > 0;)
    if (plan.draggable[i] && plan.ground[i]) points.push_back({i});
  return points;
}

QString dragPointName(const k::Mechanism& mechanism, k::PointId point) {
  return point.index < mechanism.points.size() ? pointDisplayName(mechanism.points[point.index].name) : QString();
}

QString dragHint(const k::Design& design, const k::Mechanism& mechanism, k::PointId point) {
  if (std::holds_alternative<k::FourBarDesign>(design))
    if (const auto handle = fourBarHandleOn(point)) return handleHint(*handle);
  if (point.index >= mechanism.points.size()) return {};
  return std::visit(HintOf{dragPointName(mechanism, point)}, mechanism.points[point.index].definition);
}

}  // namespace linkwright::ui
