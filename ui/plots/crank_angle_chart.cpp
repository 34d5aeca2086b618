#include "ui/plots/crank_angle_chart.h"

#include "ui/colors.h"
#include "ui/plots/plot_area_alignment.h"
#include "ui/plots/plot_axes.h"
#include "ui/plots/plot_grid.h"

#include <QChart>
#include <QChartView>
#include <QFontMetricsF>
#include <QGraphicsTextItem>
#include <QLegend>
#include <QPen>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <functional>

namespace linkwright::ui {

QChart* makeCrankAngleChart(const QString& title, QValueAxis* xAxis, QValueAxis* yAxis) {
  auto* chart = new QChart;
  chart->setTitle(title);
  // The data changes at frame rate while dragging; animations would lag behind it.
  chart->setAnimationOptions(QChart::NoAnimation);
  chart->setMargins(kBaseChartMargins);
  chart->setBackgroundRoundness(0);
  chart->legend()->setAlignment(Qt::AlignRight);
  // A narrow chart (1366×768, presentation mode) has Qt elide an entry ("transmiss…"); its
  // whole name is then the entry's tooltip.
  chart->legend()->setShowToolTips(true);
  chart->addAxis(xAxis, Qt::AlignBottom);
  chart->addAxis(yAxis, Qt::AlignLeft);
  xAxis->setTickType(QValueAxis::TicksDynamic);
  xAxis->setTickAnchor(0.0);
  new PlotGridItem(chart, xAxis, yAxis);  // owned by the chart
  new PlotAxesItem(chart, xAxis, yAxis);  // owned by the chart
  return chart;
}

std::unique_ptr<VerticalMarker> makeCrankCursor(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis) {
  return std::make_unique<VerticalMarker>(chart, xAxis, yAxis, QPen(colors().crankCursor, 1.5),
                                          QStringLiteral("cursor"));
}

int legendFittingHeight(const QChartView* view, int floor) {
  const QLegend* legend = view->chart()->legend();
  const QRectF area = legend->sceneBoundingRect();
  if (!legend->isVisible() || !(area.height() > 0.0)) return floor;
  // Qt lays every entry out, one below the other, whether or not the legend's height shows it
  // (its size hint does not count them): the entries' extent is what the legend needs.
  double top = area.bottom(), bottom = area.top();
  std::function<void(const QGraphicsItem*)> visit = [&](const QGraphicsItem* item) {
    if (dynamic_cast<const QGraphicsTextItem*>(item) != nullptr && item->isVisible()) {
      top = std::min(top, item->sceneBoundingRect().top());
      bottom = std::max(bottom, item->sceneBoundingRect().bottom());
    }
    for (const QGraphicsItem* child : item->childItems()) visit(child);
  };
  visit(legend);
  if (!(bottom > top)) return floor;
  // Qt centres the entries in the legend's height, so the room around them is not a measure:
  // half an entry's height above and below. The legend's height follows the view's one for one
  // (the title and the axis keep theirs).
  const double needs = (bottom - top) + QFontMetricsF(legend->font()).height();
  return std::max(floor, static_cast<int>(std::ceil(view->height() + needs - area.height())));
}

void applyAxisRange(QValueAxis* axis, const AxisRange& range) {
  // Each setter has the axes relabelled (plot_axes.h) even when the value is the same: only
  // what changed is set.
  if (axis->min() != range.min || axis->max() != range.max) axis->setRange(range.min, range.max);
  if (axis->tickCount() != range.tickCount) axis->setTickCount(range.tickCount);
  const QString format = QStringLiteral("%.%1f").arg(range.decimals);
  if (axis->labelFormat() != format) axis->setLabelFormat(format);
}

double fittedTickStep(const AxisRange& range, double widthPx, const QFont& font) {
  const double span = range.max - range.min;
  if (!(widthPx > 0.0) || !(span > 0.0) || !(range.step > 0.0)) return range.step;
  const QFontMetricsF metrics(font);
  const auto label = [&](double v) { return QString::number(v, 'f', std::max(range.decimals, 0)); };
  const double room =
      std::max(metrics.horizontalAdvance(label(range.min)), metrics.horizontalAdvance(label(range.max))) +
      metrics.horizontalAdvance(QStringLiteral("0"));
  for (double decade = 1.0; decade <= 1e6; decade *= 10.0)
    for (const double factor : {1.0, 2.0, 4.0})
      if (range.step * factor * decade * widthPx / span >= room) return range.step * factor * decade;
  return span;
}

void applyTickStep(QValueAxis* axis, const AxisRange& range, double widthPx) {
  const double step = fittedTickStep(range, widthPx, axis->labelsFont());
  if (axis->tickInterval() != step) axis->setTickInterval(step);
}

}  // namespace linkwright::ui
