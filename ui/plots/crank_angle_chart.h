#pragma once
// What the kinematics and force charts share: a chart of values against crank angle (title,
// no animation, the common margins, legend on the right, a value axis below with ticks
// anchored at 0° and one at the left), its red crank cursor, and the rounded axis ranges.

#include "ui/plots/axis_range.h"
#include "ui/plots/vertical_marker.h"

#include <QString>

#include <memory>

class QChart;
class QChartView;
class QFont;
class QValueAxis;

namespace linkwright::ui {

/// A new chart titled `title` holding `xAxis` (crank angle) and `yAxis`; the caller's view
/// takes ownership with setChart().
QChart* makeCrankAngleChart(const QString& title, QValueAxis* xAxis, QValueAxis* yAxis);

/// The crank-angle cursor of such a chart.
std::unique_ptr<VerticalMarker> makeCrankCursor(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis);

/// The least height of `view`, at least `floor`, at which its legend shows every entry: a short
/// chart cut the last ones off at the legend's foot ("rocker limit" on a 1366×768 laptop). From
/// the legend's own size hint against the height it has, so it holds at any font size.
int legendFittingHeight(const QChartView* view, int floor);

/// Applies a rounded range to a value axis (bounds, ticks, label format).
void applyAxisRange(QValueAxis* axis, const AxisRange& range);

/// The x axis's tick step for `range` on a plot area `widthPx` wide, its labels in `font`:
/// range.step, or the least of its multiples ×2, ×4, ×10, ×20, ×40, … at which the labels keep
/// a digit's width apart (Qt Charts ran "0 90 180270360" together on a projector's 1024 px in
/// presentation mode). range.step before the chart's first layout (no width yet).
double fittedTickStep(const AxisRange& range, double widthPx, const QFont& font);

/// Sets `axis`'s dynamic tick interval to fittedTickStep for its chart's plot area, if it differs.
void applyTickStep(QValueAxis* axis, const AxisRange& range, double widthPx);

}  // namespace linkwright::ui
