#pragma once
// A sliding block: a rounded rectangle turned along its guide, pixel-sized at any zoom, with
// its pin (drawn by the joint's handle) at the centre. The piston of a slider-crank, the ram of
// a shaper, the block a slotted link slides on.

#include <QColor>
#include <QGraphicsItem>

namespace linkwright::ui {

class SliderBlockItem : public QGraphicsItem {
public:
  /// `lengthPx` × `heightPx` at presentation scale 1.
  SliderBlockItem(const QColor& color, double lengthPx, double heightPx, QGraphicsItem* parent = nullptr);

  /// Centre at `centre` (scene units), long side along `direction` (scene axes, y up; any length).
  void place(const QPointF& centre, const QPointF& direction);
  QPointF direction() const { return m_direction; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  QColor m_color;
  double m_length;
  double m_height;
  QPointF m_direction{1.0, 0.0};  // unit, item pixels (y down)
};

}  // namespace linkwright::ui
