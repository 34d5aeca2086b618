#pragma once
// A polygon vector's label as a textbook prints it: "A^n_CB" becomes A with a superscript n
// and a subscript CB, "V_BB'" V with the subscript BB'. Drawn beside an arrow, on the side
// its normal points to, on a white ground so that lines under it do not hide it.

#include <QColor>
#include <QPointF>
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

/// Draws `label` next to `anchor`, moved `gap` pixels along the unit vector `normal` plus
/// half its own extent that way, in `colour`, with the painter's font.
void drawVectorLabel(QPainter& painter, const QString& label, QPointF anchor, QPointF normal, double gap,
                     const QColor& colour);

}  // namespace linkwright::ui
