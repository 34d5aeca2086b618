#pragma once
// A velocity or acceleration arrow at a joint: its length in scene units is the quantity times
// a scale the scene fixes per design, its head and stroke are pixel-sized, and a label at the
// tip gives the magnitude with its unit ("12.3 mm/s").

#include <QColor>
#include <QGraphicsItem>

namespace linkwright::ui {

class LabelItem;

class ArrowItem : public QGraphicsItem {
public:
  explicit ArrowItem(const QColor& color, QGraphicsItem* parent = nullptr);

  /// From `start` along `vector` (both scene units), labelled `label`.
  void setArrow(const QPointF& start, const QPointF& vector, const QString& label);
  void setPresentationScale(double factor);

  QPointF start() const { return m_start; }
  QPointF vector() const { return m_vector; }
  QString label() const;

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  QColor m_color;
  QPointF m_start;
  QPointF m_vector;
  double m_scale = 1.0;
  LabelItem* m_label;
};

}  // namespace linkwright::ui
