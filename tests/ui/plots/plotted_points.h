#pragma once
// What a plot panel plots for a quantity: all the samples its line stands for, segment after
// segment (sweep order), for tests that compare them with the core's numbers. (The series
// hold only the vertices the screen needs: screen_simplify_test.cpp checks those.)

#include "ui/plots/plot_panel.h"
#include "ui/plots/quantity_chart_view.h"

#include <QLineSeries>
#include <QList>
#include <QPointF>

namespace linkwright::ui::test {

inline QList<QPointF> plotted(const PlotPanel& panel, PlotQuantity q) {
  return panel.chartView(quantityKind(q))->samples(q);
}

}  // namespace linkwright::ui::test
