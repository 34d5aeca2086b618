#include "ui/canvas/slotted_link_item.h"

#include "ui/canvas/canvas_style.h"

#include <QGraphicsLineItem>
#include <QPen>

namespace linkwright::ui {

namespace {
constexpr double kBarPx = 16.0;
constexpr double kSlotPx = 8.0;

QPen cosmetic(const QColor& color, double width) {
  QPen pen(color, width, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin);
  pen.setCosmetic(true);
  return pen;
}
}  // namespace

SlottedLinkItem::SlottedLinkItem(const QColor& color, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_color(color), m_bar(new QGraphicsLineItem(this)),
      m_slotEdge(new QGraphicsLineItem(this)), m_slot(new QGraphicsLineItem(this)) {
  setFlag(ItemHasNoContents);
  setZValue(canvas::z::kLinks);
  applyPens();
}

void SlottedLinkItem::setGeometry(const QPointF& pivot, const QPointF& barEnd, const QPointF& slotStart,
                                  const QPointF& slotEnd) {
  m_bar->setLine(QLineF(pivot, barEnd));
  m_slotEdge->setLine(QLineF(slotStart, slotEnd));
  m_slot->setLine(QLineF(slotStart, slotEnd));
}

QLineF SlottedLinkItem::bar() const { return m_bar->line(); }
QLineF SlottedLinkItem::slot() const { return m_slot->line(); }

void SlottedLinkItem::setPresentationScale(double factor) {
  m_scale = factor;
  applyPens();
}

void SlottedLinkItem::applyPens() {
  m_bar->setPen(cosmetic(m_color, kBarPx * m_scale));
  m_slotEdge->setPen(cosmetic(m_color.darker(150), (kSlotPx + 2.0) * m_scale));
  m_slot->setPen(cosmetic(Qt::white, kSlotPx * m_scale));
}

}  // namespace linkwright::ui
