#include "ui/canvas/actuator_item.h"

#include "ui/canvas/canvas_style.h"

#include <QGraphicsLineItem>
#include <QPen>

#include <cmath>

namespace linkwright::ui {

namespace {

constexpr double kBarrelWidthPx = 14.0;
constexpr double kBarrelWallPx = 1.5;
constexpr double kRodWidthPx = 5.0;
constexpr QColor kRodColor{150, 150, 160};

QPen cosmetic(const QColor& color, double width) {
  QPen pen(color, width, Qt::SolidLine, Qt::FlatCap, Qt::MiterJoin);
  pen.setCosmetic(true);
  return pen;
}

}  // namespace

ActuatorItem::ActuatorItem(QGraphicsItem* parent)
    : QGraphicsItem(parent), m_barrelOutline(new QGraphicsLineItem(this)), m_barrelFill(new QGraphicsLineItem(this)),
      m_rod(new QGraphicsLineItem(this)) {
  setFlag(ItemHasNoContents);
  setZValue(canvas::z::kLinks - 0.1);
  m_rod->setZValue(-1.0);  // under the barrel it slides out of
  applyPens();
}

void ActuatorItem::setBarrel(double length) { m_barrel = length; }

void ActuatorItem::setEnds(const QPointF& base, const QPointF& end) {
  const QPointF d = end - base;
  const double length = std::hypot(d.x(), d.y());
  const QPointF barrelEnd = length > 0.0 ? base + d * (std::min(m_barrel, length) / length) : base;
  m_barrelOutline->setLine(QLineF(base, barrelEnd));
  m_barrelFill->setLine(QLineF(base, barrelEnd));
  m_rod->setLine(QLineF(base, end));
}

QLineF ActuatorItem::rodLine() const { return m_rod->line(); }
QLineF ActuatorItem::barrelLine() const { return m_barrelOutline->line(); }

void ActuatorItem::setPresentationScale(double factor) {
  m_scale = factor;
  applyPens();
}

void ActuatorItem::applyPens() {
  m_barrelOutline->setPen(cosmetic(colors().pinOutline, kBarrelWidthPx * m_scale));
  m_barrelFill->setPen(cosmetic(colors().groundFill, (kBarrelWidthPx - 2.0 * kBarrelWallPx) * m_scale));
  m_rod->setPen(cosmetic(kRodColor, kRodWidthPx * m_scale));
}

}  // namespace linkwright::ui
