#include "ui/canvas/link_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPen>

namespace linkwright::ui {

LinkItem::LinkItem(const QColor& color, QGraphicsItem* parent) : QGraphicsLineItem(parent) {
  QPen pen(color, canvas::kLinkWidthPx, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  setPen(pen);
  setZValue(canvas::z::kLinks);
}

void LinkItem::setPresentationScale(double factor) {
  QPen p = pen();
  p.setWidthF(canvas::kLinkWidthPx * factor);
  setPen(p);
}

QRectF LinkItem::boundingRect() const {
  const double half = pen().widthF() / 2.0;
  return QRectF(line().p1(), line().p2()).normalized().adjusted(-half, -half, half, half);
}

}  // namespace linkwright::ui
