#include "ui/plots/quantity_chart_view.h"

#include "ui/plots/plot_area_alignment.h"

#include <QChart>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::ui {
namespace {

QPen cursorPen() { return QPen(QColor(0xc0, 0x20, 0x20), 1.5); }

QPointF nearestByX(const QList<QPointF>& points, qreal x) {
  QPointF best = points.isEmpty() ? QPointF(x, 0.0) : points.front();
  qreal bestDistance = std::numeric_limits<qreal>::infinity();
  for (const QPointF& p : points) {
    const qreal d = std::abs(p.x() - x);
    if (d < bestDistance) {
      bestDistance = d;
      best = p;
    }
  }
  return best;
}

} // namespace

QuantityChartView::QuantityChartView(QuantityKind kind, const QString& title, QWidget* parent)
    : QChartView(parent), m_kind(kind), m_xAxis(new QValueAxis), m_yAxis(new QValueAxis) {
  auto* chart = new QChart;
  chart->setTitle(title);
  // Animations would make every edit and drag lag behind; the data changes at frame rate.
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(kBaseChartMargins);
  chart->setBackgroundRoundness(0);
  chart->legend()->setAlignment(Qt::AlignRight);
  chart->addAxis(m_xAxis, Qt::AlignBottom);
  chart->addAxis(m_yAxis, Qt::AlignLeft);
  m_xAxis->setTickType(QValueAxis::TicksDynamic);
  m_xAxis->setTickAnchor(0.0);
  setChart(chart);  // the view owns the chart, the chart its axes and series
  setRenderHint(QPainter::Antialiasing);
  // OpenGL stays off (the default): a few 721-point lines draw well under a frame in
  // software, and the OpenGL path cannot be exported as SVG.

  m_cursor = std::make_unique<VerticalMarker>(chart, m_xAxis, m_yAxis, cursorPen(), QStringLiteral("cursor"));
}

QuantityChartView::~QuantityChartView() = default;

void QuantityChartView::setCurves(const std::vector<PlotCurve>& curves) {
  std::vector<PlotCurve> mine;
  for (const PlotCurve& c : curves)
    if (quantityKind(c.quantity) == m_kind) mine.push_back(c);
  const bool same = mine.size() == m_curves.size() &&
                    std::equal(mine.begin(), mine.end(), m_curves.begin(), [](const PlotCurve& a, const Curve& b) { return a == b.curve; });
  if (same) return;
  for (Curve& curve : m_curves) curve.line.removeFromChart();
  m_curves.clear();
  m_curves.reserve(mine.size());
  for (const PlotCurve& c : mine) {
    const PlotQuantity q = c.quantity;
    auto hover = [this, q](QLineSeries* segment) {
      connect(segment, &QXYSeries::hovered, this,
              [this, q, segment](const QPointF& p, bool inside) { onSegmentHovered(q, segment, p, inside); });
    };
    m_curves.push_back({c, SegmentedLine(chart(), m_xAxis, m_yAxis, {c.key, c.name, c.color}, hover)});
  }
  m_cursor->raise();  // over the curves, as before they were replaced
}

void QuantityChartView::setData(const kinematics::SweepResult& sweep, const QuantitySelection& selection,
                                AngleUnit unit, double fromDeg, double toDeg, const QString& lengthUnit) {
  m_values.clear();
  for (Curve& curve : m_curves) {
    const bool shown = selection.contains(curve.curve.quantity);
    if (shown)
      buildSeriesRuns(sweep, curve.curve.quantity, unit, m_runs);
    else
      m_runs.runs.clear();
    for (const QList<QPointF>& run : m_runs.runs)
      for (const QPointF& p : run) m_values.push_back(p.y());
    curve.line.setRuns(m_runs, shown);
  }
  // Spikes next to a toggle would squash every other value flat: they run off the chart
  // instead, and the hover read-out still gives their value.
  constexpr double kNone = std::numeric_limits<double>::infinity();
  const auto [lo, hi] = m_values.empty() ? std::pair<double, double>{kNone, -kNone} : robustSpan(m_values);
  m_valueRange = niceValueRange(lo, hi);
  applyAxis(m_yAxis, m_valueRange);
  m_yAxis->setTitleText(valueAxisTitle(m_kind, unit, lengthUnit));
  const AxisRange x = crankAxisRange(fromDeg, toDeg, unit);
  applyAxis(m_xAxis, x);
  m_xAxis->setTickInterval(x.step);
  m_xAxis->setTitleText(crankAxisTitle(unit));
  m_cursor->setYSpan(m_valueRange.min, m_valueRange.max);
}

void QuantityChartView::applyAxis(QValueAxis* axis, const AxisRange& range) {
  axis->setRange(range.min, range.max);
  axis->setTickCount(range.tickCount);
  axis->setLabelFormat(QStringLiteral("%.%1f").arg(range.decimals));
}

void QuantityChartView::resizeEvent(QResizeEvent* event) {
  QChartView::resizeEvent(event);
  emit resized();
}

void QuantityChartView::setCursorX(std::optional<double> x) { m_cursor->setX(x); }

QList<QLineSeries*> QuantityChartView::segments(PlotQuantity quantity) const {
  for (const Curve& curve : m_curves)
    if (curve.curve.quantity == quantity) return curve.line.segments();
  return {};
}

void QuantityChartView::onSegmentHovered(PlotQuantity quantity, const QLineSeries* segment, QPointF point,
                                         bool inside) {
  emit curveHovered(quantity, nearestByX(segment->points(), point.x()), inside);
}

} // namespace linkwright::ui
