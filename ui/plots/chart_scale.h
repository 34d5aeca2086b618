#pragma once
// Presentation mode for charts. A lecture hall reads a chart only if its text and lines grow
// with the rest of the window, but Qt Charts takes its fonts from the chart theme, not from the
// widget, so a window font change leaves them at their small defaults. This scales a chart's
// title, legend, axis labels and titles, every series' pen and point labels, from the sizes
// they had at scale 1 (remembered on the chart, its axes and series the first time they are
// scaled).

#include <QFont>

class QChart;
class QXYSeries;

namespace linkwright::ui {

/// Draws `chart`'s text and lines at `factor` times their scale-1 sizes (clamped to 0.5–4).
void setChartScale(QChart* chart, double factor);
/// The factor `chart` is drawn at: 1 unless setChartScale said otherwise.
double chartScale(const QChart* chart);
/// A pen width of `width` at scale 1, for a series added to `chart` now.
/// The point-label font of `series` at `chart`'s scale (its font at scale 1 is kept on the
/// series the first time): the rocker limits' "limit" grows with the rest in presentation mode.
QFont scaledPointLabelsFont(const QChart* chart, QXYSeries* series);

double scaledPenWidth(const QChart* chart, double width);

}  // namespace linkwright::ui
