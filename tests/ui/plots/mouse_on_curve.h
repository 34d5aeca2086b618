#pragma once
// Points the mouse at a chart as a user does (a move event to the view's viewport), for tests
// of what hovering a curve reads out.

#include "ui/plots/curve_item.h"
#include "ui/plots/plot_panel.h"

#include <QChart>
#include <QChartView>
#include <QCoreApplication>
#include <QTest>

#include <cmath>

namespace linkwright::ui::test {

/// Shows `panel` at `size` and settles it: the timers left from showing it then change neither
/// the sweep nor the axes while a test points at its charts. False if it was never exposed.
inline bool showSettled(PlotPanel& panel, QSize size) {
  panel.resize(size);
  panel.show();
  if (!QTest::qWaitForWindowExposed(&panel)) return false;
  panel.reportPlotWidth();
  panel.settleValueRanges();
  QCoreApplication::processEvents();
  return true;
}

/// The viewport pixel that holds the point where `view`'s `curve` draws `value` (plot units).
inline QPoint pixelOf(const QChartView& view, const CurveItem& curve, QPointF value) {
  const QPointF at = view.viewportTransform().map(view.chart()->mapToScene(curve.toChart(value)));
  return {static_cast<int>(std::floor(at.x())), static_cast<int>(std::floor(at.y()))};
}

/// The plot units `curve` draws at the top left corner of viewport pixel `pixel` of `view`,
/// where a mouse at `pixel` points.
inline QPointF valueAt(const QChartView& view, const CurveItem& curve, QPoint pixel) {
  return curve.toValue(view.chart()->mapFromScene(view.mapToScene(pixel)));
}

/// Moves the mouse to `pixel` of `view`'s viewport (the view shown and laid out).
inline void moveMouse(QChartView& view, QPoint pixel) { QTest::mouseMove(view.viewport(), pixel); }

}  // namespace linkwright::ui::test
