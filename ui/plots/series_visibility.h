#pragma once
// Showing and hiding chart series while keeping helper series out of the legend. Qt Charts
// re-shows a series' legend marker whenever the series becomes visible, so the marker's
// visibility has to be set again after every change of the series'. It is set even when
// QLegendMarker::isVisible() already says so: that reads the graphics item's effective
// visibility, false while the legend's item group is hidden (until the first layout).

#include <QAbstractSeries>
#include <QChart>
#include <QLegend>
#include <QLegendMarker>

namespace linkwright::ui {

/// Shows or hides `series` on `chart`; its legend entry is shown only if `inLegend` too.
inline void setSeriesShown(QChart* chart, QAbstractSeries* series, bool shown, bool inLegend) {
  if (series->isVisible() != shown) series->setVisible(shown);
  const bool markerShown = shown && inLegend;
  for (QLegendMarker* marker : chart->legend()->markers(series)) marker->setVisible(markerShown);
}

}  // namespace linkwright::ui
