#include "ui/plots/chart_colors.h"

#include "ui/colors.h"

#include <QAbstractAxis>
#include <QBrush>
#include <QChart>
#include <QLegend>
#include <QPen>
#include <QVariant>

namespace linkwright::ui {

namespace {

// What `object` had before the first call, stored under `key`; `current` the first time.
template <typename T>
T own(QObject* object, const char* key, const T& current) {
  const QVariant stored = object->property(key);
  if (stored.isValid()) return stored.value<T>();
  object->setProperty(key, QVariant::fromValue(current));
  return current;
}

QPen recoloured(QPen pen, const QColor& color) {
  pen.setColor(color);
  return pen;
}

}  // namespace

void applyChartColors(QChart* chart) {
  const std::optional<ChartColors>& c = colors().chart;
  const QBrush background = own(chart, "linkwrightOwnBackground", chart->backgroundBrush());
  const QBrush title = own(chart, "linkwrightOwnTitleBrush", chart->titleBrush());
  const QColor legend = own(chart->legend(), "linkwrightOwnLabelColor", chart->legend()->labelColor());
  chart->setBackgroundBrush(c ? QBrush(c->background) : background);
  chart->setTitleBrush(c ? QBrush(c->text) : title);
  chart->legend()->setLabelColor(c ? c->text : legend);
  for (QAbstractAxis* axis : chart->axes()) {
    const QBrush labels = own(axis, "linkwrightOwnLabelsBrush", axis->labelsBrush());
    const QBrush axisTitle = own(axis, "linkwrightOwnTitleBrush", axis->titleBrush());
    const QPen line = own(axis, "linkwrightOwnLinePen", axis->linePen());
    const QPen grid = own(axis, "linkwrightOwnGridPen", axis->gridLinePen());
    axis->setLabelsBrush(c ? QBrush(c->text) : labels);
    axis->setTitleBrush(c ? QBrush(c->text) : axisTitle);
    axis->setLinePen(c ? recoloured(line, c->axisLine) : line);
    axis->setGridLinePen(c ? recoloured(grid, c->grid) : grid);
  }
}

}  // namespace linkwright::ui
