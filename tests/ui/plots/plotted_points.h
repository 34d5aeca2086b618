#pragma once
// What a plot panel draws for a quantity: all the points of its line, segment after segment
// (sweep order), for tests that compare them with the core's numbers.

#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include <QLineSeries>
#include <QList>
#include <QPointF>

namespace linkwright::ui::test {

inline QList<QPointF> plotted(const PlotPanel& panel, PlotQuantity q) {
  QList<QPointF> points;
  for (const QLineSeries* segment : panel.chartView(quantityKind(q))->segments(q)) points += segment->points();
  return points;
}

}  // namespace linkwright::ui::test
