#pragma once
// A joint the user can grab: a pin (white circle, dark outline) for B and C, a filled dot for
// the coupler point P, a small square for a vertex of a driven point's path. Pixel-sized at any
// zoom; pos() is the joint in scene coordinates.

#include <QColor>
#include <QGraphicsItem>

namespace linkwright::ui {

class JointHandleItem : public QGraphicsItem {
public:
  enum class Style { Pin, Dot, Vertex };
  explicit JointHandleItem(Style style, const QColor& dotColor = Qt::black, QGraphicsItem* parent = nullptr);

  /// Highlighted while the pointer is over it or it is being dragged.
  void setHot(bool hot);
  bool isHot() const { return m_hot; }

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  Style m_style;
  QColor m_dotColor;
  bool m_hot = false;
};

}  // namespace linkwright::ui
