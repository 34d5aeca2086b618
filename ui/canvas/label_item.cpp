#include "ui/canvas/label_item.h"

#include "ui/canvas/canvas_style.h"

#include <QFontMetricsF>
#include <QPainter>

#include <cmath>

namespace linkwright::ui {

namespace {
constexpr double kBoxPaddingPx = 3.0;
}

LabelItem::LabelItem(QGraphicsItem* parent) : QGraphicsItem(parent) {
  setFlag(ItemIgnoresTransformations);
  m_font.setPointSizeF(canvas::kLabelPointSize);
  m_layout.setTextFormat(Qt::PlainText);
  setZValue(canvas::z::kLabels);
}

void LabelItem::layOut() {
  const QFontMetricsF metrics(m_font);
  m_size = m_maximumWidth > 0.0
               ? metrics.boundingRect(QRectF(0.0, 0.0, m_maximumWidth, 1e6), Qt::TextWordWrap, m_text).size()
               : QSizeF(metrics.horizontalAdvance(m_text), metrics.height());
  m_layout.setText(m_text);
  m_layout.setTextWidth(m_maximumWidth > 0.0 ? m_maximumWidth : -1.0);
  m_layout.prepare(QTransform(), m_font);
}

void LabelItem::setText(const QString& text) {
  if (text == m_text) return;
  prepareGeometryChange();
  m_text = text;
  layOut();
}

void LabelItem::setColor(const QColor& color) {
  m_color = color;
  update();
}

void LabelItem::setBoxed(bool boxed) {
  prepareGeometryChange();
  m_boxed = boxed;
}

void LabelItem::setBackdrop(bool backdrop) {
  m_backdrop = backdrop;
  update();
}

void LabelItem::setMaximumWidth(double pixels) {
  if (pixels == m_maximumWidth) return;
  prepareGeometryChange();
  m_maximumWidth = pixels;
  layOut();
}

void LabelItem::setPlacement(const QPointF& offsetPx, Qt::Alignment alignment) {
  prepareGeometryChange();
  m_offset = offsetPx;
  m_alignment = alignment;
}

void LabelItem::placeToward(const QPointF& direction, double distancePx) {
  const double length = std::hypot(direction.x(), direction.y());
  const QPointF unit = length > 0.0 ? direction / length : QPointF(0.7071067811865476, 0.7071067811865476);
  Qt::Alignment alignment = unit.x() > 0.3 ? Qt::AlignLeft : (unit.x() < -0.3 ? Qt::AlignRight : Qt::AlignHCenter);
  alignment |= unit.y() > 0.3 ? Qt::AlignBottom : (unit.y() < -0.3 ? Qt::AlignTop : Qt::AlignVCenter);
  setPlacement(QPointF(unit.x(), -unit.y()) * distancePx, alignment);  // item pixels have y down
}

QRectF LabelItem::textRect() const {
  const QSizeF size = m_size;
  QPointF topLeft = m_offset;
  if (m_alignment & Qt::AlignRight) topLeft.rx() -= size.width();
  else if (m_alignment & Qt::AlignHCenter) topLeft.rx() -= size.width() / 2.0;
  if (m_alignment & Qt::AlignBottom) topLeft.ry() -= size.height();
  else if (m_alignment & Qt::AlignVCenter) topLeft.ry() -= size.height() / 2.0;
  return {topLeft, size};
}

QRectF LabelItem::boundingRect() const {
  if (m_text.isEmpty()) return {};
  // The rect also covers the anchor: QGraphicsView::render (image export) finds items by
  // their bounding rect taken as scene units, and at high zoom or in a metre-sized design a
  // rect offset from the anchor by pixels would miss the view and drop the label.
  return textRect()
      .adjusted(-kBoxPaddingPx - 1.0, -kBoxPaddingPx - 1.0, kBoxPaddingPx + 1.0, kBoxPaddingPx + 1.0)
      .united(QRectF(-1.0, -1.0, 2.0, 2.0));
}

void LabelItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  if (m_text.isEmpty()) return;
  const QRectF rect = textRect();
  const QColor color = m_color.value_or(colors().label);
  if (m_boxed) {
    painter->setPen(QPen(color, 1.0));
    painter->setBrush(colors().labelBox);
    painter->drawRoundedRect(rect.adjusted(-kBoxPaddingPx, -kBoxPaddingPx, kBoxPaddingPx, kBoxPaddingPx), 3.0, 3.0);
  } else if (m_backdrop) {
    painter->fillRect(rect.adjusted(-1.0, 0.0, 1.0, 0.0), colors().labelBox);
  }
  painter->setFont(m_font);
  painter->setPen(color);
  // Centred in the box upright, as drawText with AlignVCenter would.
  const double top = rect.top() + (rect.height() - m_layout.size().height()) / 2.0;
  painter->drawStaticText(QPointF(rect.left(), top), m_layout);
}

}  // namespace linkwright::ui
