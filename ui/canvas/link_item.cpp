#include "ui/canvas/link_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPen>

namespace linkwright::ui {

LinkItem::LinkItem(const QColor& color, QGraphicsItem* parent) : QGraphicsLineItem(parent) {
  // Flat ends: each end is a joint, whose pin covers it. Qt's raster engine draws a thick line
  // with flat or square caps as one antialiased quad, and strokes a round-capped one as a
  // path: on a six-bar the links were a quarter of the canvas's repaint.
  QPen pen(color, canvas::kLinkWidthPx, Qt::SolidLine, Qt::FlatCap, Qt::RoundJoin);
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
