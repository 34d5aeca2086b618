#pragma once
// Points the mouse at a chart as a user does (a move event to the view's viewport), for tests
// of what hovering a curve reads out.

#include "ui/plots/curve_item.h"

#include <QChart>
#include <QChartView>
#include <QTest>

#include <cmath>

namespace linkwright::ui::test {

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
