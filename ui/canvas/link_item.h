#pragma once
// A moving link drawn as a bar between its two joints: a wide cosmetic stroke with round caps,
// so it keeps its pixel width at any zoom. Ends are in scene (model) coordinates.

#include <QColor>
#include <QGraphicsLineItem>

namespace linkwright::ui {

class LinkItem : public QGraphicsLineItem {
public:
  explicit LinkItem(const QColor& color, QGraphicsItem* parent = nullptr);

  void setEnds(const QPointF& first, const QPointF& second) { setLine(QLineF(first, second)); }
  /// Width is the canvas's link width times `factor` (1 normal, 2 presentation).
  void setPresentationScale(double factor);
  /// The line's box grown by half the pen's width, as QGraphicsLineItem's, without stroking
  /// the line into a path on every call (the scene asks on every move of a drag).
  QRectF boundingRect() const override;
};

}  // namespace linkwright::ui
