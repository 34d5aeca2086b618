#pragma once
// A slotted link (the RPR dyad's link, the shaper's rocker): a wide bar from its pivot, with a
// slot cut along it where the block pinned at the crank slides. The bar runs from the pivot
// past both the tip and the farthest point the block reaches; the slot spans the block's
// travel. Cosmetic strokes: the bar and the slot keep their pixel widths at any zoom.

#include <QColor>
#include <QGraphicsItem>

class QGraphicsLineItem;

namespace linkwright::ui {

class SlottedLinkItem : public QGraphicsItem {
public:
  explicit SlottedLinkItem(const QColor& color, QGraphicsItem* parent = nullptr);

  /// The bar from `pivot` to `barEnd`, the slot from `slotStart` to `slotEnd` (scene units).
  void setGeometry(const QPointF& pivot, const QPointF& barEnd, const QPointF& slotStart, const QPointF& slotEnd);
  QLineF bar() const;
  QLineF slot() const;
  void setPresentationScale(double factor);

  QRectF boundingRect() const override { return {}; }
  void paint(QPainter*, const QStyleOptionGraphicsItem*, QWidget*) override {}

private:
  void applyPens();

  QColor m_color;
  double m_scale = 1.0;
  QGraphicsLineItem* m_bar;
  QGraphicsLineItem* m_slotEdge;
  QGraphicsLineItem* m_slot;
};

}  // namespace linkwright::ui
