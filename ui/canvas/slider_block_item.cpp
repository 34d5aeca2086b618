#include "ui/canvas/slider_block_item.h"

#include "ui/canvas/canvas_style.h"

#include <QPainter>

#include <cmath>

namespace linkwright::ui {

SliderBlockItem::SliderBlockItem(const QColor& color, double lengthPx, double heightPx, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_color(color), m_length(lengthPx), m_height(heightPx) {
  setFlag(ItemIgnoresTransformations);
  setZValue(canvas::z::kBlocks);
}

void SliderBlockItem::place(const QPointF& centre, const QPointF& direction) {
  setPos(centre);
  const double length = std::hypot(direction.x(), direction.y());
  if (!(length > 0.0)) return;
  // Item pixels have y down while the scene has y up: the view flips y, nothing else.
  const QPointF unit(direction.x() / length, -direction.y() / length);
  if (unit == m_direction) return;
  m_direction = unit;
  update();
}

QRectF SliderBlockItem::boundingRect() const {
  const double r = 0.5 * std::hypot(m_length, m_height) + 2.0;
  return {-r, -r, 2.0 * r, 2.0 * r};
}

void SliderBlockItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  painter->setRenderHint(QPainter::Antialiasing);
  // A rotation built from the unit direction itself: x along the guide, y across it.
  painter->setTransform(QTransform(m_direction.x(), m_direction.y(), -m_direction.y(), m_direction.x(), 0.0, 0.0),
                        true);
  const QRectF body(-m_length / 2.0, -m_height / 2.0, m_length, m_height);
  QColor fill = m_color.lighter(165);
  fill.setAlpha(235);
  painter->setPen(QPen(m_color.darker(130), canvas::kOutlineWidthPx));
  painter->setBrush(fill);
  painter->drawRoundedRect(body, 2.5, 2.5);
  // Two grooves near the ends read as a piston or a ram rather than a plain box.
  painter->setPen(QPen(m_color.darker(110), 1.0));
  for (const double x : {-0.32 * m_length, 0.32 * m_length})
    painter->drawLine(QPointF(x, -m_height / 2.0 + 2.0), QPointF(x, m_height / 2.0 - 2.0));
}

}  // namespace linkwright::ui
