#pragma once
// A short text on the canvas that keeps its pixel size and stays upright at any zoom: point
// names, arrow magnitudes, the crank's range, the reason a drag was refused.

#include <QColor>
#include <QFont>
#include <QGraphicsItem>
#include <QStaticText>
#include <QString>

#include <optional>

namespace linkwright::ui {

class LabelItem : public QGraphicsItem {
public:
  explicit LabelItem(QGraphicsItem* parent = nullptr);

  void setText(const QString& text);
  QString text() const { return m_text; }
  /// The text's colour; until set, the theme's label colour (colors().label) when drawn.
  void setColor(const QColor& color);
  /// Draws a white rounded box behind the text (for messages over the drawing).
  void setBoxed(bool boxed);
  /// Fills the text's box with the label box colour, unoutlined, so a label over a link or a
  /// ground's hatching still reads (force magnitudes).
  void setBackdrop(bool backdrop);
  /// Wraps the text at word boundaries to at most `pixels` wide (0: one line).
  void setMaximumWidth(double pixels);
  /// Where the text sits relative to pos(): `offsetPx` pixels away, and which side of the
  /// text box touches that point (AlignLeft: the box starts there; AlignBottom: box above).
  void setPlacement(const QPointF& offsetPx, Qt::Alignment alignment);
  /// Places the text `distancePx` away from pos() in `direction` (scene axes, y up), on that
  /// side of the point: to the right for +x, above for +y, and so on.
  void placeToward(const QPointF& direction, double distancePx);

  /// The text's box in item pixels, without the box's padding.
  QRectF textRect() const;

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

private:
  // Lays the text out once per change: a drag repaints every label on every move, and shaping
  // the text each time was most of their cost.
  void layOut();

  QString m_text;
  QStaticText m_layout;           // the text, shaped and wrapped
  QSizeF m_size;                  // its box, as the font's metrics measure it
  std::optional<QColor> m_color;  // nullopt: the theme's
  QFont m_font;
  bool m_boxed = false;
  bool m_backdrop = false;
  double m_maximumWidth = 0.0;
  QPointF m_offset;
  Qt::Alignment m_alignment = Qt::AlignLeft | Qt::AlignBottom;
};

}  // namespace linkwright::ui
