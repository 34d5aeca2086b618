#pragma once
// A linear actuator (a hydraulic cylinder) from its base pin to its end: a wide barrel from the
// base, of a fixed length, and a narrower rod that slides out of it to the end. The barrel's
// length is set once per design (setBarrel), so only the rod seems to move as the actuator
// extends.

#include <QGraphicsItem>
#include <QLineF>

class QGraphicsLineItem;

namespace linkwright::ui {

class ActuatorItem : public QGraphicsItem {
public:
  explicit ActuatorItem(QGraphicsItem* parent = nullptr);

  /// The barrel's length (scene units): a little less than the actuator's shortest length.
  void setBarrel(double length);
  /// From the base pin to the end pin (scene units).
  void setEnds(const QPointF& base, const QPointF& end);
  void setPresentationScale(double factor);
  /// The rod's line, base to end, and the barrel's, base to its mouth (scene units).
  QLineF rodLine() const;
  QLineF barrelLine() const;

  QRectF boundingRect() const override { return {}; }
  void paint(QPainter*, const QStyleOptionGraphicsItem*, QWidget*) override {}

private:
  void applyPens();

  double m_barrel = 0.0;
  double m_scale = 1.0;
  QGraphicsLineItem* m_barrelOutline;
  QGraphicsLineItem* m_barrelFill;
  QGraphicsLineItem* m_rod;
};

}  // namespace linkwright::ui
