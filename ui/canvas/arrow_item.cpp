#include "ui/canvas/arrow_item.h"

#include "ui/canvas/canvas_style.h"
#include "ui/canvas/label_item.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

ArrowItem::ArrowItem(const QColor& color, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_color(color), m_label(new LabelItem(this)) {
  setZValue(canvas::z::kArrows);
  m_label->setColor(color.darker(120));
  m_label->setPlacement(QPointF(6.0, -4.0), Qt::AlignLeft | Qt::AlignBottom);
}

void ArrowItem::setArrow(const QPointF& start, const QPointF& vector, const QString& label) {
  prepareGeometryChange();
  m_start = start;
  m_vector = vector;
  m_label->setText(label);
  m_label->setPos(start + vector);
}

void ArrowItem::setPresentationScale(double factor) {
  m_scale = factor;
  m_label->setScale(factor);
  update();
}

QString ArrowItem::label() const { return m_label->text(); }

QRectF ArrowItem::boundingRect() const {
  // The head is pixel-sized; a quarter of the arrow's length around it covers it whenever the
  // arrow is long enough to be worth drawing.
  const double pad = 0.25 * std::hypot(m_vector.x(), m_vector.y());
  return QRectF(m_start, m_start + m_vector).normalized().adjusted(-pad, -pad, pad, pad);
}

void ArrowItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  // Draw in device pixels so the head keeps its size and shape under the view's y flip.
  const QTransform toDevice = painter->worldTransform();
  const QPointF tail = toDevice.map(m_start);
  const QPointF tip = toDevice.map(m_start + m_vector);
  const QLineF shaft(tail, tip);
  const double length = shaft.length();
  if (!(length > 1.0)) return;
  painter->save();
  painter->resetTransform();
  painter->setRenderHint(QPainter::Antialiasing);
  const double head = std::min(canvas::kArrowHeadPx * m_scale, 0.6 * length);
  const QPointF unit = (tip - tail) / length;
  const QPointF normal(-unit.y(), unit.x());
  const QPointF base = tip - head * unit;
  painter->setPen(QPen(m_color, canvas::kArrowWidthPx * m_scale, Qt::SolidLine, Qt::RoundCap));
  painter->drawLine(tail, base);
  painter->setPen(Qt::NoPen);
  painter->setBrush(m_color);
  const QPointF triangle[] = {tip, base + 0.4 * head * normal, base - 0.4 * head * normal};
  painter->drawPolygon(triangle, 3);
  painter->restore();
}

}  // namespace linkwright::ui
