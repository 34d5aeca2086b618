#pragma once
// A ground pivot (O2, O4) drawn as the textbook support: a pin on a triangle standing on a
// hatched base. Pixel-sized at any zoom; pos() is the pivot in scene (model) coordinates.

#include <QGraphicsItem>

namespace linkwright::ui {

class GroundPivotItem : public QGraphicsItem {
public:
  explicit GroundPivotItem(QGraphicsItem* parent = nullptr);

  /// Highlighted while the pointer is over it or it is being dragged.
  void setHot(bool hot);
  bool isHot() const { return m_hot; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  bool m_hot = false;
};

}  // namespace linkwright::ui
