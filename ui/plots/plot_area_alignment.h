#pragma once
// Lines up the plot areas of charts stacked in one column, so that the same crank angle sits
// at the same screen x on every chart and the cursor reads across them. Differing y-label
// and legend widths are evened out by widening the left and right chart margins; the charts
// keep their automatic layout, so they still adapt when resized.

#include <QList>
#include <QMargins>

class QChart;

namespace linkwright::ui {

/// Margins every chart gets before alignment adds to them.
inline const QMargins kBaseChartMargins(2, 2, 2, 2);

/// Aligns the plot areas of `charts` (equal widths, one above the other) horizontally, each
/// chart laid out afresh.
void alignPlotAreas(const QList<QChart*>& charts);
/// The same when only the charts in `changed` have new axes, titles or legend entries since
/// the last alignment: the others keep their layout, and only their margins may change.
void alignPlotAreas(const QList<QChart*>& charts, const QList<QChart*>& changed);

}  // namespace linkwright::ui
