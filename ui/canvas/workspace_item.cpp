#include "ui/canvas/workspace_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPainterPath>
#include <QPen>

namespace linkwright::ui {

namespace {
constexpr QColor kWorkspaceFill{49, 130, 189, 22};
constexpr QColor kWorkspaceEdge{49, 130, 189, 120};
}  // namespace

WorkspaceItem::WorkspaceItem(QGraphicsItem* parent) : QGraphicsPathItem(parent) {
  setZValue(canvas::z::kFrame - 0.5);  // behind everything: it is the ground the arm works over
  setBrush(kWorkspaceFill);
  setPresentationScale(1.0);
}

void WorkspaceItem::setAnnulus(const QPointF& centre, double inner, double outer) {
  QPainterPath ring;
  ring.setFillRule(Qt::OddEvenFill);
  ring.addEllipse(centre, outer, outer);
  if (inner > 0.0) ring.addEllipse(centre, inner, inner);
  setPath(ring);
}

void WorkspaceItem::setPresentationScale(double factor) {
  QPen pen(kWorkspaceEdge, 1.0 * factor, Qt::DashLine);
  pen.setCosmetic(true);
  setPen(pen);
}

}  // namespace linkwright::ui
