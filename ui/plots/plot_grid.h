#pragma once
// The grid of a chart's plot area, drawn by one item of ours in place of Qt Charts' own.
// Qt Charts strokes each grid line antialiased, at fractional pixels, as a separate item, and a
// drag repaints the plot areas on every move: that was a third of the charts' repaint. This
// item draws each line as one aliased row or column of pixels (the one where Qt's blurred line
// was darkest), at the ticks Qt Charts places, under the curves and the axes as Qt's grid was.

#include <QGraphicsObject>
#include <QRectF>

#include <vector>

class QChart;
class QValueAxis;

namespace linkwright::ui {

/// Where Qt Charts puts `axis`'s major ticks, in pixels along an axis whose minimum is drawn
/// at `from` and its maximum at `to` (ChartValueAxisX/Y::calculateLayout): `tickCount` evenly
/// spaced for fixed ticks; for dynamic ones, every `tickInterval` from the `tickAnchor` within
/// the range. Empty for an empty range.
std::vector<double> majorTickPixels(const QValueAxis& axis, double from, double to);
/// The values of those ticks, in the same order.
std::vector<double> majorTickValues(const QValueAxis& axis);

/// The pixel row or column an aliased one-pixel line takes for Qt's line at `pixel`.
int gridPixel(double pixel);

class PlotGridItem : public QGraphicsObject {
public:
  /// Hides the grid lines of `xAxis` and `yAxis` (horizontal and vertical axes of `chart`) and
  /// draws them instead, in each axis's grid pen; the chart owns the item.
  PlotGridItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis);

  QRectF boundingRect() const override;
  void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

  /// The columns of the vertical lines and the rows of the horizontal ones, as painted.
  std::vector<int> columns() const;
  std::vector<int> rows() const;

private:
  void follow(QValueAxis* axis);  // repaints when what places or colours its lines changes

  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  QRectF m_area;  // the plot area, chart coordinates
};

}  // namespace linkwright::ui
