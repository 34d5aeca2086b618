#include "ui/canvas/ground_pivot_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPainter>

#include <algorithm>

namespace linkwright::ui {

namespace {
// Item coordinates are pixels with y down (the item ignores the view's y flip).
constexpr double kHalfBase = 11.0;
constexpr double kHeight = 16.0;
constexpr double kHatchDepth = 6.0;
constexpr double kHatchStep = 5.0;
}  // namespace

GroundPivotItem::GroundPivotItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
  setFlag(ItemIgnoresTransformations);
  setZValue(canvas::z::kGround);
}

void GroundPivotItem::setHot(bool hot) {
  if (hot == m_hot) return;
  m_hot = hot;
  update();
}

QRectF GroundPivotItem::boundingRect() const {
  const double r = canvas::kHotRadiusPx + 1.0;
  const double w = kHalfBase + 5.0;
  return QRectF(QPointF(-std::max(r, w), -r), QPointF(std::max(r, w), kHeight + kHatchDepth + 2.0));
}

void GroundPivotItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->setRenderHint(QPainter::Antialiasing);
  if (m_hot) {
    painter->setPen(Qt::NoPen);
    painter->setBrush(colors().hot);
    painter->drawEllipse(QPointF(0, 0), canvas::kHotRadiusPx, canvas::kHotRadiusPx);
  }
  QPen pen(colors().pinOutline, canvas::kOutlineWidthPx);
  pen.setJoinStyle(Qt::RoundJoin);
  painter->setPen(pen);
  painter->setBrush(colors().groundFill);
  const QPointF triangle[] = {{0.0, 0.0}, {-kHalfBase * 0.75, kHeight}, {kHalfBase * 0.75, kHeight}};
  painter->drawPolygon(triangle, 3);
  painter->drawLine(QPointF(-kHalfBase - 3.0, kHeight), QPointF(kHalfBase + 3.0, kHeight));
  QPen hatch(colors().pinOutline, 1.0);
  painter->setPen(hatch);
  for (double x = -kHalfBase; x <= kHalfBase + 3.0; x += kHatchStep)
    painter->drawLine(QPointF(x, kHeight), QPointF(x - kHatchDepth, kHeight + kHatchDepth));
  painter->setPen(pen);
  painter->setBrush(colors().pinFill);
  painter->drawEllipse(QPointF(0, 0), canvas::kPinRadiusPx, canvas::kPinRadiusPx);
}

}  // namespace linkwright::ui
