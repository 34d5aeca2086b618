#pragma once
// The scale grid behind the linkage, in the user's length unit: line spacing from the 1-2-5
// sequence so lines are 40 to 100 pixels apart at any zoom, numbers along the left and bottom
// edges, and the unit in the corner.

#include <QFont>
#include <QRectF>
#include <QString>
#include <QTransform>

#include <vector>

class QPainter;

namespace linkwright::ui {

/// Minimum distance between grid lines, pixels.
inline constexpr double kMinGridPixels = 40.0;

/// The smallest spacing s = {1, 2, 5}·10^k (model units) with s·pixelsPerUnit ≥ minPixels;
/// the next smaller step is under minPixels, so s·pixelsPerUnit < 2.5·minPixels. Returns 1 for
/// a non-positive or non-finite scale.
double gridSpacing(double pixelsPerUnit, double minPixels = kMinGridPixels);

/// A grid coordinate written with as many decimals as the spacing needs ("0.05", "120").
QString formatGridValue(double value, double spacing);

/// The grid numbers' font: `font` at 8 pt times `textScale`.
QFont gridLabelFont(QFont font, double textScale);

/// One grid number or the caption, in device pixels: drawn from `at` (its baseline's left end),
/// `box` the text's extent.
struct GridLabel {
  QPointF at;
  QString text;
  QRectF box;
};

/// The numbers along the left and bottom edges of `visible` (scene rect, `toDevice` mapping it
/// to device pixels) and the caption "grid S unit" at the bottom right, in `font`: none
/// overlaps another, and the bottom numbers keep at least a digit's width apart (a number only
/// every 2, 5, 10… lines where the lines are closer than the numbers are wide: presentation mode
/// on a projector's canvas).
std::vector<GridLabel> gridLabels(const QTransform& toDevice, const QRectF& visible, double spacing,
                                  const QString& unit, const QFont& font, double textScale);

/// Paints the grid over `exposed` (scene rect) with `painter` set up in scene coordinates
/// (y up), labelling the edges of `visible` (the view's scene rect). `unit` is the length
/// unit; `textScale` enlarges the numbers in presentation mode.
void paintGrid(QPainter* painter, const QRectF& exposed, const QRectF& visible, const QString& unit, double textScale);

}  // namespace linkwright::ui
