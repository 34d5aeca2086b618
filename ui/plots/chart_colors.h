#pragma once
// A chart's frame and text in the current theme (ui/colors.h). Qt Charts takes them from its
// chart theme, which would also reset the series' colours and the presentation-mode fonts, so
// they are set one by one instead: the background, the title, the legend, and each axis's
// labels, title, line and grid. The Normal theme shows the chart theme's own, remembered on the
// chart and its axes the first time.

class QChart;

namespace linkwright::ui {

/// Gives `chart` (and every axis it has now) the current theme's frame and text colours.
void applyChartColors(QChart* chart);

}  // namespace linkwright::ui
