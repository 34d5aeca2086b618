#include "ui/classroom/vector_label.h"

#include "ui/colors.h"

#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

VectorLabelParts splitVectorLabel(const QString& label) {
  VectorLabelParts parts;
  const qsizetype sub = label.indexOf('_');
  const qsizetype sup = label.indexOf('^');
  const qsizetype symbolEnd = std::min(sub < 0 ? label.size() : sub, sup < 0 ? label.size() : sup);
  parts.symbol = label.left(symbolEnd);
  if (sup >= 0) parts.superscript = label.mid(sup + 1, (sub > sup ? sub : label.size()) - sup - 1);
  if (sub >= 0) parts.subscript = label.mid(sub + 1);
  return parts;
}

namespace {
QFont smallFont(const QFont& base) {
  QFont small = base;
  small.setPointSizeF(base.pointSizeF() * 0.72);
  return small;
}
}  // namespace

QRectF vectorLabelRect(const QFont& font, const QString& label, QPointF anchor, QPointF normal, double gap) {
  const VectorLabelParts parts = splitVectorLabel(label);
  const QFontMetricsF fm(font);
  const QFontMetricsF sm(smallFont(font));
  const double width = fm.horizontalAdvance(parts.symbol) +
                       std::max(sm.horizontalAdvance(parts.superscript), sm.horizontalAdvance(parts.subscript)) + 2.0;
  const double height = fm.height() + 0.5 * sm.height();
  // The centre moves off the line until the box clears it.
  const double clear = 0.5 * (width * std::abs(normal.x()) + height * std::abs(normal.y()));
  const QPointF centre = anchor + normal * (gap + clear);
  return {centre.x() - width / 2.0, centre.y() - height / 2.0, width, height};
}

void drawVectorLabel(QPainter& painter, const QString& label, const QRectF& box, const QColor& colour) {
  const VectorLabelParts parts = splitVectorLabel(label);
  const QFont base = painter.font();
  const QFont small = smallFont(base);
  const QFontMetricsF fm(base);
  const QFontMetricsF sm(small);
  painter.setPen(Qt::NoPen);
  painter.setBrush(colors().labelBox);
  painter.drawRoundedRect(box.adjusted(-2, -1, 2, 1), 3, 3);
  painter.setPen(colour);
  const double symbolWidth = fm.horizontalAdvance(parts.symbol);
  const double baseline = box.top() + fm.ascent() + 0.2 * sm.height();
  painter.drawText(QPointF(box.left(), baseline), parts.symbol);
  painter.setFont(small);
  if (!parts.superscript.isEmpty())
    painter.drawText(QPointF(box.left() + symbolWidth + 1.0, baseline - 0.45 * fm.ascent()), parts.superscript);
  if (!parts.subscript.isEmpty())
    painter.drawText(QPointF(box.left() + symbolWidth + 1.0, baseline + 0.35 * sm.ascent()), parts.subscript);
  painter.setFont(base);
}

}  // namespace linkwright::ui
