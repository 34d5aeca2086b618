#pragma once
// A polygon vector's label as a textbook prints it: "A^n_CB" becomes A with a superscript n
// and a subscript CB, "V_BB'" V with the subscript BB'. Drawn beside an arrow, on the side
// its normal points to, on a white ground so that lines under it do not hide it.

#include <QColor>
#include <QFont>
#include <QPointF>
#include <QRectF>
#include <QString>

class QPainter;

namespace linkwright::ui {

/// The parts of `label`: the symbol, the superscript (after '^') and the subscript (after '_').
struct VectorLabelParts {
  QString symbol;
  QString superscript;
  QString subscript;
};
VectorLabelParts splitVectorLabel(const QString& label);

/// The box `label` takes with `font`, centred `gap` pixels plus half its own extent from
/// `anchor` along the unit vector `normal`: beside an arrow, clear of its line.
QRectF vectorLabelRect(const QFont& font, const QString& label, QPointF anchor, QPointF normal, double gap);

/// Draws `label` in `box` (from vectorLabelRect) in `colour`, with the painter's font.
void drawVectorLabel(QPainter& painter, const QString& label, const QRectF& box, const QColor& colour);

}  // namespace linkwright::ui
