#include "ui/canvas/slideway_item.h"

#include "ui/canvas/canvas_style.h"

#include <QGraphicsLineItem>
#include <QPen>

namespace linkwright::ui {

namespace {
constexpr double kWallPx = 1.5;   // wall stroke
constexpr double kHatchPx = 7.0;  // depth of the hatching outside each wall

QPen cosmetic(const QBrush& brush, double width, Qt::PenStyle style = Qt::SolidLine) {
  QPen pen(brush, width, style, Qt::FlatCap, Qt::MiterJoin);
  pen.setCosmetic(true);
  return pen;
}
}  // namespace

SlidewayItem::SlidewayItem(bool onGround, double clearancePx, const QColor& color, QGraphicsItem* parent)
    : QGraphicsItem(parent), m_onGround(onGround), m_clearance(clearancePx), m_color(color),
      m_hatch(new QGraphicsLineItem(this)), m_walls(new QGraphicsLineItem(this)), m_inside(new QGraphicsLineItem(this)),
      m_axis(new QGraphicsLineItem(this)) {
  setFlag(ItemHasNoContents);
  setZValue(onGround ? canvas::z::kSlideway : canvas::z::kLinks + 0.1);
  // One line drawn as nested bands: hatching, then the walls, then the white gap between them.
  m_hatch->setVisible(onGround);
  m_walls->setVisible(onGround);
  m_inside->setVisible(onGround);
  applyPens();
}

void SlidewayItem::setEnds(const QPointF& start, const QPointF& end) {
  for (QGraphicsLineItem* item : {m_hatch, m_walls, m_inside, m_axis}) item->setLine(QLineF(start, end));
}

QLineF SlidewayItem::line() const { return m_axis->line(); }

void SlidewayItem::setPresentationScale(double factor) {
  m_scale = factor;
  applyPens();
}

void SlidewayItem::applyPens() {
  const double inside = m_clearance * m_scale;
  const double walls = inside + 2.0 * kWallPx * m_scale;
  m_hatch->setPen(cosmetic(QBrush(colors().pinOutline, Qt::BDiagPattern), walls + 2.0 * kHatchPx * m_scale));
  m_walls->setPen(cosmetic(colors().pinOutline, walls));
  m_inside->setPen(cosmetic(Qt::white, inside));
  if (m_onGround) m_axis->setPen(cosmetic(colors().frame, 1.0 * m_scale, Qt::DashDotLine));
  else m_axis->setPen(cosmetic(m_color, 2.0 * m_scale, Qt::DashLine));
}

}  // namespace linkwright::ui
