#include "ui/plots/polar_load_view.h"

#include "ui/plots/chart_view_setup.h"
#include "ui/plots/force_chart_view.h"
#include "ui/plots/plot_area_alignment.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/plot_grid.h"
#include "ui/plots/segmented_line.h"
#include "ui/plots/series_visibility.h"

#include <QChart>
#include <QLegend>
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace {
constexpr qreal kDotSizePx = 9.0;
const QColor kOriginColor(150, 150, 150);
const QColor kDotColor(0xc0, 0x20, 0x20);  // the crank cursor's colour on the other charts
}  // namespace

PolarLoadView::PolarLoadView(QWidget* parent)
    : QChartView(parent), m_xAxis(new QValueAxis), m_yAxis(new QValueAxis), m_originX(new QLineSeries),
      m_originY(new QLineSeries), m_dot(new QScatterSeries) {
  auto* chart = new QChart;
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(kBaseChartMargins);
  chart->setBackgroundRoundness(0);
  chart->legend()->setVisible(false);
  chart->addAxis(m_xAxis, Qt::AlignBottom);
  chart->addAxis(m_yAxis, Qt::AlignLeft);
  m_xAxis->setTitleText(tr("Fx [N]"));
  m_yAxis->setTitleText(tr("Fy [N]"));
  for (QValueAxis* axis : {m_xAxis, m_yAxis}) {
    axis->setTickType(QValueAxis::TicksDynamic);
    axis->setTickAnchor(0.0);
  }
  new PlotGridItem(chart, m_xAxis, m_yAxis);  // owned by the chart
  new PlotAxesItem(chart, m_xAxis, m_yAxis);  // owned by the chart
  setChart(chart);
  setUpChartView(this);
  m_originX->setObjectName(QStringLiteral("origin_x"));
  m_originY->setObjectName(QStringLiteral("origin_y"));
  for (QLineSeries* line : {m_originX, m_originY}) {
    line->setPen(QPen(kOriginColor, 1.0));
    chart->addSeries(line);
    line->attachAxis(m_xAxis);
    line->attachAxis(m_yAxis);
  }
  m_dot->setObjectName(QStringLiteral("current"));
  m_dot->setMarkerSize(kDotSizePx);
  m_dot->setColor(kDotColor);
  m_dot->setBorderColor(Qt::white);
  chart->addSeries(m_dot);
  m_dot->attachAxis(m_xAxis);
  m_dot->attachAxis(m_yAxis);
  // The plot area moves when tick labels change width: keep the scales equal after each layout.
  connect(chart, &QChart::plotAreaChanged, this, [this] { equalizeScales(); });
}

void PolarLoadView::setLocus(const SeriesRuns& locus, const QString& title, const QColor& color) {
  chart()->setTitle(title);
  if (!m_locus || m_locus->style().color != color) {
    if (m_locus) m_locus->removeFromChart();
    m_locus.emplace(chart(), m_xAxis, m_yAxis, SegmentedLine::Style{QStringLiteral("locus"), QString(), color});
    // Keep the dot on top of the locus.
    chart()->removeSeries(m_dot);
    chart()->addSeries(m_dot);
    m_dot->attachAxis(m_xAxis);
    m_dot->attachAxis(m_yAxis);
  }
  m_pointCount = locus.pointCount();
  m_xLo = m_xHi = m_yLo = m_yHi = 0.0;
  for (const QList<QPointF>& run : locus.runs)
    for (const QPointF& p : run) {
      m_xLo = std::min(m_xLo, p.x());
      m_xHi = std::max(m_xHi, p.x());
    }
  if (!locus.empty()) {
    m_yLo = std::min(0.0, locus.minY);
    m_yHi = std::max(0.0, locus.maxY);
  }
  equalizeScales();  // the axes first: the locus is simplified for their scale
  m_locus->setRuns(locus, true);
}

void PolarLoadView::setCurrent(std::optional<QPointF> force) {
  if (force) m_dot->replace(QList<QPointF>{*force});
  else if (m_dot->count() > 0) m_dot->replace(QList<QPointF>{});
  setSeriesShown(chart(), m_dot, force.has_value(), false);
  if (!force) return;
  const bool outside = force->x() < m_xLo || force->x() > m_xHi || force->y() < m_yLo || force->y() > m_yHi;
  if (!outside) return;
  m_xLo = std::min(m_xLo, force->x());
  m_xHi = std::max(m_xHi, force->x());
  m_yLo = std::min(m_yLo, force->y());
  m_yHi = std::max(m_yHi, force->y());
  equalizeScales();
}

void PolarLoadView::equalizeScales() {
  // Nothing to fit before the first layout: the plot area is empty, and Qt Charts has been
  // seen to loop between an axis and its domain when ranges are set on such a chart.
  if (m_equalizing) return;
  const QRectF area = chart()->plotArea();
  if (area.width() < 1.0 || area.height() < 1.0) return;
  m_equalizing = true;
  const AxisRange x = niceValueRange(m_xLo, m_xHi);
  const AxisRange y = niceValueRange(m_yLo, m_yHi);
  // One scale for both axes: the one that fits both rounded ranges; the other axis widens
  // about its centre.
  const double perPixel = std::max((x.max - x.min) / area.width(), (y.max - y.min) / area.height());
  const double xMid = 0.5 * (x.min + x.max);
  const double yMid = 0.5 * (y.min + y.max);
  const double xHalf = 0.5 * perPixel * area.width();
  const double yHalf = 0.5 * perPixel * area.height();
  // One tick step on both axes, so the grid is square; at least a few ticks on the shorter.
  const double step = niceStep(2.0 * std::min(xHalf, yHalf) / 4.0);
  // Only what changed: every axis setter has the axes relabelled (crank_angle_chart.h).
  const QString format = QStringLiteral("%.%1f").arg(decimalsFor(step));
  for (QValueAxis* axis : {m_xAxis, m_yAxis}) {
    if (axis->tickInterval() != step) axis->setTickInterval(step);
    if (axis->labelFormat() != format) axis->setLabelFormat(format);
  }
  if (m_xAxis->min() != xMid - xHalf || m_xAxis->max() != xMid + xHalf) {
    m_xAxis->setRange(xMid - xHalf, xMid + xHalf);
    m_originX->replace(QList<QPointF>{{xMid - xHalf, 0.0}, {xMid + xHalf, 0.0}});
  }
  if (m_yAxis->min() != yMid - yHalf || m_yAxis->max() != yMid + yHalf) {
    m_yAxis->setRange(yMid - yHalf, yMid + yHalf);
    m_originY->replace(QList<QPointF>{{0.0, yMid - yHalf}, {0.0, yMid + yHalf}});
  }
  m_equalizing = false;
  // A new scale (a resize, a dot outside the locus): the locus is simplified again if it matters.
  if (m_locus) m_locus->rescale();
}

double PolarLoadView::xScale() const { return (m_xAxis->max() - m_xAxis->min()) / chart()->plotArea().width(); }
double PolarLoadView::yScale() const { return (m_yAxis->max() - m_yAxis->min()) / chart()->plotArea().height(); }

}  // namespace linkwright::ui
