#include "ui/plots/plot_grid.h"

#include <QChart>
#include <QPainter>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace {

// Qt Charts' grid layer (ChartPresenter::GridZValue): above the chart's background and plot
// area, below the axes and the series.
constexpr qreal kGridZ = 2.0;
constexpr int kMaxTicks = 1000;
constexpr double kEdgeSlackPx = 1e-6;

}  // namespace

std::vector<double> majorTickPixels(const QValueAxis& axis, double from, double to) {
  const double min = axis.min(), max = axis.max();
  if (!(max > min)) return {};
  if (axis.isReverse()) std::swap(from, to);
  std::vector<double> pixels;
  if (axis.tickType() == QValueAxis::TicksFixed) {
    const int count = axis.tickCount();
    if (count < 2) return {};
    for (int i = 0; i < count; ++i) pixels.push_back(from + i * (to - from) / (count - 1));
    return pixels;
  }
  const double perUnit = (to - from) / (max - min);
  for (const double value : majorTickValues(axis)) pixels.push_back(from + (value - min) * perUnit);
  return pixels;
}

std::vector<double> majorTickValues(const QValueAxis& axis) {
  const double min = axis.min(), max = axis.max();
  if (!(max > min)) return {};
  std::vector<double> values;
  if (axis.tickType() == QValueAxis::TicksFixed) {
    const int count = axis.tickCount();
    if (count < 2) return {};
    for (int i = 0; i < count; ++i) values.push_back(min + i * (max - min) / (count - 1));
    return values;
  }
  const double interval = axis.tickInterval();
  if (!(interval > 0.0)) return {};
  const double anchor = axis.tickAnchor();
  // As Qt Charts does, but bounded: a tick interval far below the range would hang the paint.
  double value = anchor - std::floor((anchor - min) / interval) * interval;
  for (int i = 0; value <= max && i < kMaxTicks; ++i, value += interval) values.push_back(value);
  return values;
}

int gridPixel(double pixel) { return static_cast<int>(std::floor(pixel)); }

PlotGridItem::PlotGridItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis)
    : QGraphicsObject(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_area(chart->plotArea()) {
  setZValue(kGridZ);
  setAcceptedMouseButtons(Qt::NoButton);  // the curves' hover and the view's gestures pass through
  follow(xAxis);
  follow(yAxis);
  connect(chart, &QChart::plotAreaChanged, this, [this](const QRectF& area) {
    prepareGeometryChange();
    m_area = area;
  });
}

void PlotGridItem::follow(QValueAxis* axis) {
  axis->setGridLineVisible(false);
  const auto repaint = [this] { update(); };
  connect(axis, &QValueAxis::rangeChanged, this, repaint);
  connect(axis, &QValueAxis::tickCountChanged, this, repaint);
  connect(axis, &QValueAxis::tickIntervalChanged, this, repaint);
  connect(axis, &QValueAxis::tickAnchorChanged, this, repaint);
  connect(axis, &QValueAxis::tickTypeChanged, this, repaint);
  connect(axis, &QAbstractAxis::reverseChanged, this, repaint);
  connect(axis, &QAbstractAxis::gridLinePenChanged, this, repaint);
  connect(axis, &QAbstractAxis::gridLineColorChanged, this, repaint);
}

QRectF PlotGridItem::boundingRect() const { return m_area.adjusted(-1.0, -1.0, 1.0, 1.0); }

namespace {

// The pixels of the ticks within [lo, hi]. A tick on an edge may land a rounding error
// outside, where Qt Charts would leave its line out: it is kept, on the edge.
std::vector<int> pixelsWithin(const std::vector<double>& ticks, double lo, double hi) {
  std::vector<int> pixels;
  for (const double t : ticks)
    if (t >= lo - kEdgeSlackPx && t <= hi + kEdgeSlackPx) pixels.push_back(gridPixel(std::clamp(t, lo, hi)));
  return pixels;
}

}  // namespace

std::vector<int> PlotGridItem::columns() const {
  return pixelsWithin(majorTickPixels(*m_xAxis, m_area.left(), m_area.right()), m_area.left(), m_area.right());
}

std::vector<int> PlotGridItem::rows() const {
  return pixelsWithin(majorTickPixels(*m_yAxis, m_area.bottom(), m_area.top()), m_area.top(), m_area.bottom());
}

void PlotGridItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  if (m_area.isEmpty()) return;
  // Filled one-pixel rectangles: the raster engine fills them row by row, with none of the
  // stroker's work for a line, even an aliased one.
  const int top = gridPixel(m_area.top()), bottom = gridPixel(m_area.bottom());
  const int left = gridPixel(m_area.left()), right = gridPixel(m_area.right());
  const QBrush columnBrush = m_xAxis->gridLinePen().brush(), rowBrush = m_yAxis->gridLinePen().brush();
  for (const int x : columns()) painter->fillRect(QRect(x, top, 1, bottom - top + 1), columnBrush);
  for (const int y : rows()) painter->fillRect(QRect(left, y, right - left + 1, 1), rowBrush);
}

}  // namespace linkwright::ui
