#include "ui/canvas/joint_handle_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPainter>

namespace linkwright::ui {

JointHandleItem::JointHandleItem(Style style, const QColor& dotColor, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_style(style), m_dotColor(dotColor) {
  setFlag(ItemIgnoresTransformations);
  setZValue(canvas::z::kPins);
}

void JointHandleItem::setHot(bool hot) {
  if (hot == m_hot) return;
  m_hot = hot;
  update();
}

QRectF JointHandleItem::boundingRect() const {
  const double r = canvas::kHotRadiusPx + 1.0;
  return {-r, -r, 2.0 * r, 2.0 * r};
}

void JointHandleItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->setRenderHint(QPainter::Antialiasing);
  if (m_hot) {
    painter->setPen(Qt::NoPen);
    painter->setBrush(colors().hot);
    painter->drawEllipse(QPointF(0, 0), canvas::kHotRadiusPx, canvas::kHotRadiusPx);
  }
  if (m_style == Style::Pin) {
    painter->setPen(QPen(colors().pinOutline, canvas::kOutlineWidthPx));
    painter->setBrush(colors().pinFill);
    painter->drawEllipse(QPointF(0, 0), canvas::kPinRadiusPx, canvas::kPinRadiusPx);
  } else if (m_style == Style::Vertex) {
    painter->setPen(QPen(colors().pinOutline, canvas::kOutlineWidthPx));
    painter->setBrush(colors().groundFill);
    const double half = canvas::kDotRadiusPx;
    painter->drawRect(QRectF(-half, -half, 2.0 * half, 2.0 * half));
  } else {
    painter->setPen(QPen(Qt::white, 1.0));
    painter->setBrush(m_dotColor);
    painter->drawEllipse(QPointF(0, 0), canvas::kDotRadiusPx, canvas::kDotRadiusPx);
  }
}

}  // namespace linkwright::ui
