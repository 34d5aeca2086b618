#include "ui/plots/curve_item.h"

#include <QChart>
#include <QGraphicsSceneHoverEvent>
#include <QPainter>
#include <QPainterPathStroker>
#include <QValueAxis>
#include <QXYSeries>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace linkwright::ui {

namespace {

// Qt Charts' series layer (ChartPresenter::SeriesZValue): over the grid and the axes, under
// the legend. Among the series, the later made is drawn over the earlier, as before.
constexpr qreal kSeriesZ = 4.0;
// How far from the line (pixels, beyond its half width) the mouse still points at it.
constexpr qreal kHoverReachPx = 3.0;

// The squared distance from `p` to the segment from `a` to `b`.
qreal squaredDistance(QPointF p, QPointF a, QPointF b) {
  const QPointF ab = b - a;
  const qreal length2 = QPointF::dotProduct(ab, ab);
  const qreal t = length2 > 0.0 ? std::clamp(QPointF::dotProduct(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  const QPointF d = p - (a + t * ab);
  return QPointF::dotProduct(d, d);
}

}  // namespace

CurveItem::CurveItem(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, const QXYSeries* legendEntry)
    : QGraphicsObject(chart), m_xAxis(xAxis), m_yAxis(yAxis), m_legendEntry(legendEntry), m_area(chart->plotArea()) {
  setZValue(kSeriesZ);
  setAcceptHoverEvents(true);
  setAcceptedMouseButtons(Qt::NoButton);  // the view's gestures pass through
  connect(chart, &QChart::plotAreaChanged, this, [this](const QRectF& area) {
    m_area = area;
    placeBounds();
  });
  for (QValueAxis* axis : {xAxis, yAxis}) {
    connect(axis, &QValueAxis::rangeChanged, this, &CurveItem::placeBounds);
    connect(axis, &QAbstractAxis::reverseChanged, this, &CurveItem::placeBounds);
  }
  connect(legendEntry, &QXYSeries::penChanged, this, &CurveItem::placeBounds);
}

void CurveItem::setRuns(QList<QList<QPointF>> runs) {
  m_runs = std::move(runs);
  // (By hand: QRectF::united skips a zero-size rectangle, such as one point's.)
  constexpr double kInf = std::numeric_limits<double>::infinity();
  QPointF least(kInf, kInf), most(-kInf, -kInf);
  for (const QList<QPointF>& run : m_runs)
    for (const QPointF& p : run) {
      least = {std::min(least.x(), p.x()), std::min(least.y(), p.y())};
      most = {std::max(most.x(), p.x()), std::max(most.y(), p.y())};
    }
  m_hasVertices = least.x() <= most.x();
  m_valueBounds = QRectF(least, most);
  m_shapeMapping.reset();
  placeBounds();
  update();
  emit runsReplaced();
}

void CurveItem::placeBounds() {
  // Only the part of the plot area the line covers is repainted when it changes (as Qt Charts
  // did for a series): a curve in one band of the chart leaves the rest alone.
  prepareGeometryChange();
  m_bounds = QRectF();
  if (!m_hasVertices) return;
  const Mapping m = mapping();
  if (m.scale.x() == 0.0 || m.scale.y() == 0.0) return;
  const qreal margin = 0.5 * m.penWidth + kHoverReachPx + 1.0;  // the line's width and its hover outline
  const QRectF line = QRectF(m(m_valueBounds.topLeft()), m(m_valueBounds.bottomRight())).normalized();
  m_bounds = line.adjusted(-margin, -margin, margin, margin) & m_area.adjusted(-1.0, -1.0, 1.0, 1.0);
}

QPen CurveItem::pen() const { return m_legendEntry->pen(); }

CurveItem::Mapping CurveItem::mapping() const {
  Mapping m;
  m.penWidth = pen().widthF();
  const double xSpan = m_xAxis->max() - m_xAxis->min();
  const double ySpan = m_yAxis->max() - m_yAxis->min();
  if (!(xSpan > 0.0) || !(ySpan > 0.0)) return m;  // scale 0: nothing is drawn
  // x grows rightwards and y upwards, unless the axis is reversed.
  const double sx = (m_xAxis->isReverse() ? -1.0 : 1.0) * m_area.width() / xSpan;
  const double sy = (m_yAxis->isReverse() ? 1.0 : -1.0) * m_area.height() / ySpan;
  const double x0 = m_xAxis->isReverse() ? m_area.right() : m_area.left();
  const double y0 = m_yAxis->isReverse() ? m_area.top() : m_area.bottom();
  m.scale = {sx, sy};
  m.offset = {x0 - m_xAxis->min() * sx, y0 - m_yAxis->min() * sy};
  return m;
}

QPointF CurveItem::toChart(QPointF value) const { return mapping()(value); }

QPointF CurveItem::toValue(QPointF point) const {
  const Mapping m = mapping();
  if (m.scale.x() == 0.0 || m.scale.y() == 0.0) return {};
  return {(point.x() - m.offset.x()) / m.scale.x(), (point.y() - m.offset.y()) / m.scale.y()};
}

QRectF CurveItem::boundingRect() const { return m_bounds; }

QRectF CurveItem::clipRect() const {
  // Qt Charts' clip for a line series (LineChartItem::paint): the plot area widened by the
  // fractions of a pixel that let a line along an edge show, never by a whole pixel.
  const auto fraction = [](qreal v) { return v - static_cast<int>(v); };
  const qreal x1 = fraction(m_area.left());
  const qreal y1 = fraction(m_area.top());
  const qreal x2 = fraction(m_area.width() + 0.5);
  const qreal y2 = fraction(m_area.height() + 0.5);
  return m_area.adjusted(-x1, -y1, std::max(x1, x2), std::max(y1, y2));
}

QPainterPath CurveItem::shape() const {
  const Mapping m = mapping();
  if (m_shapeMapping == m) return m_shape;
  QPainterPath lines;
  for (const QList<QPointF>& run : m_runs) {
    if (run.isEmpty()) continue;
    lines.moveTo(m(run.front()));
    for (qsizetype i = 1; i < run.size(); ++i) lines.lineTo(m(run[i]));
  }
  QPainterPathStroker stroker;
  stroker.setWidth(m.penWidth + 2.0 * kHoverReachPx);
  stroker.setCapStyle(Qt::RoundCap);
  stroker.setJoinStyle(Qt::RoundJoin);
  m_shape = stroker.createStroke(lines);
  m_shapeMapping = m;
  return m_shape;
}

void CurveItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*) {
  const Mapping m = mapping();
  if (m.scale.x() == 0.0 || m.scale.y() == 0.0) return;
  painter->save();
  painter->setClipRect(clipRect(), Qt::IntersectClip);
  painter->setPen(pen());
  painter->setBrush(Qt::NoBrush);
  m_segments.clear();
  for (const QList<QPointF>& run : m_runs)
    for (qsizetype i = 1; i < run.size(); ++i) m_segments.append({m(run[i - 1]), m(run[i])});
  // Separate segments, not a polyline: the raster engine draws a solid thin pen's lines
  // straight into coverage (QRasterizer::rasterizeLine), where a polyline is stroked into an
  // outline and filled, at more than twice the cost (callgrind, docs/benchmarks.md).
  painter->drawLines(m_segments.constData(), static_cast<int>(m_segments.size()));
  painter->restore();
}

qsizetype CurveItem::nearestRun(QPointF point) const {
  const Mapping m = mapping();
  qsizetype best = -1;
  qreal bestDistance = std::numeric_limits<qreal>::infinity();
  for (qsizetype r = 0; r < m_runs.size(); ++r) {
    const QList<QPointF>& run = m_runs[r];
    for (qsizetype i = 0; i < run.size(); ++i) {
      const QPointF a = m(run[i]);
      const qreal d = squaredDistance(point, a, i + 1 < run.size() ? m(run[i + 1]) : a);
      if (d < bestDistance) {
        bestDistance = d;
        best = r;
      }
    }
  }
  return best;
}

// (The scene follows every hover enter with a hover move: the move says where.)
void CurveItem::hoverMoveEvent(QGraphicsSceneHoverEvent* event) {
  // The outline reaches past the plot area where a line runs off it: there it points at nothing.
  const qsizetype run = m_area.contains(event->pos()) ? nearestRun(event->pos()) : -1;
  if (m_hoveredRun >= 0 && run != m_hoveredRun) emit hovered(m_hoveredRun, toValue(event->pos()), false);
  m_hoveredRun = run;
  if (run >= 0) emit hovered(run, toValue(event->pos()), true);
}

void CurveItem::hoverLeaveEvent(QGraphicsSceneHoverEvent* event) {
  if (m_hoveredRun >= 0) emit hovered(m_hoveredRun, toValue(event->pos()), false);
  m_hoveredRun = -1;
}

}  // namespace linkwright::ui
