#pragma once
// The guide a slider runs on. On the ground it is a slideway: two walls just clear of the
// block, hatched on the outside like the ground under a pivot, with the guide's centre line
// dash-dotted between them. On a moving link it is a thin line along that link. All strokes
// are cosmetic, so the walls keep their pixel spacing at any zoom; only the ends are in
// model units.

#include <QColor>
#include <QGraphicsItem>

class QGraphicsLineItem;

namespace linkwright::ui {

class SlidewayItem : public QGraphicsItem {
public:
  /// `clearancePx`: the wall-to-wall width inside, at presentation scale 1 (the block's height).
  SlidewayItem(bool onGround, double clearancePx, const QColor& color, QGraphicsItem* parent = nullptr);

  /// From `start` to `end` (scene units).
  void setEnds(const QPointF& start, const QPointF& end);
  QLineF line() const;
  bool onGround() const { return m_onGround; }
  void setPresentationScale(double factor);

  QRectF boundingRect() const override { return {}; }
  void paint(QPainter*, const QStyleOptionGraphicsItem*, QWidget*) override {}

private:
  void applyPens();

  bool m_onGround;
  double m_clearance;
  QColor m_color;
  double m_scale = 1.0;
  QGraphicsLineItem* m_hatch;
  QGraphicsLineItem* m_walls;
  QGraphicsLineItem* m_inside;
  QGraphicsLineItem* m_axis;
};

}  // namespace linkwright::ui
