#include "ui/plots/chart_scale.h"

#include <QAbstractAxis>
#include <QChart>
#include <QLegend>
#include <QPen>
#include <QScatterSeries>
#include <QXYSeries>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

namespace {

constexpr const char* kScale = "linkwrightChartScale";
constexpr const char* kBaseTitleFont = "linkwrightBaseTitleFont";
constexpr const char* kBaseLegendFont = "linkwrightBaseLegendFont";
constexpr const char* kBaseLabelsFont = "linkwrightBaseLabelsFont";
constexpr const char* kBasePenWidth = "linkwrightBasePenWidth";
constexpr const char* kBaseMarkerSize = "linkwrightBaseMarkerSize";

// The font `object` had at scale 1, stored under `key` the first time; `current` until then.
QFont baseFont(QObject* object, const char* key, const QFont& current) {
  const QVariant stored = object->property(key);
  if (stored.isValid()) return stored.value<QFont>();
  object->setProperty(key, current);
  return current;
}

QFont scaled(QFont font, double factor) {
  if (font.pixelSize() > 0) font.setPixelSize(std::max(1, static_cast<int>(std::lround(font.pixelSize() * factor))));
  else font.setPointSizeF(font.pointSizeF() * factor);
  return font;
}

}  // namespace

double chartScale(const QChart* chart) {
  const QVariant stored = chart->property(kScale);
  return stored.isValid() ? stored.toDouble() : 1.0;
}

QFont scaledPointLabelsFont(const QChart* chart, QXYSeries* series) {
  return scaled(baseFont(series, kBaseLabelsFont, series->pointLabelsFont()), chartScale(chart));
}

double scaledPenWidth(const QChart* chart, double width) { return width * chartScale(chart); }

void setChartScale(QChart* chart, double factor) {
  if (!std::isfinite(factor)) return;
  factor = std::clamp(factor, 0.5, 4.0);
  const double before = chartScale(chart);
  if (factor == before) return;
  chart->setTitleFont(scaled(baseFont(chart, kBaseTitleFont, chart->titleFont()), factor));
  chart->legend()->setFont(scaled(baseFont(chart->legend(), kBaseLegendFont, chart->legend()->font()), factor));
  for (QAbstractAxis* axis : chart->axes()) {
    axis->setLabelsFont(scaled(baseFont(axis, kBaseLabelsFont, axis->labelsFont()), factor));
    axis->setTitleFont(scaled(baseFont(axis, kBaseTitleFont, axis->titleFont()), factor));
  }
  for (QAbstractSeries* series : chart->series()) {
    auto* xy = qobject_cast<QXYSeries*>(series);
    if (xy == nullptr) continue;
    // A series made after the last scaling was given scaledPenWidth at `before`.
    QVariant base = xy->property(kBasePenWidth);
    if (!base.isValid()) {
      base = xy->pen().widthF() / before;
      xy->setProperty(kBasePenWidth, base);
    }
    // Qt Charts 6.4 crashes laying out an emptied scatter series (the limit points of a linkage
    // that has none) for a new pen or marker size (XYChart::offGridStatusVector). Such a series
    // takes its size from chartScale when it gets points again (LimitMarkers::setPositions).
    if (xy->count() == 0 && qobject_cast<QScatterSeries*>(xy) != nullptr) continue;
    QPen pen = xy->pen();
    pen.setWidthF(base.toDouble() * factor);
    xy->setPen(pen);
    if (xy->pointLabelsVisible())
      xy->setPointLabelsFont(scaled(baseFont(xy, kBaseLabelsFont, xy->pointLabelsFont()), factor));
    // Markers (another tool's rows) grow with the lines.
    if (auto* scatter = qobject_cast<QScatterSeries*>(xy)) {
      QVariant size = scatter->property(kBaseMarkerSize);
      if (!size.isValid()) {
        size = scatter->markerSize() / before;
        scatter->setProperty(kBaseMarkerSize, size);
      }
      scatter->setMarkerSize(size.toDouble() * factor);
    }
  }
  chart->setProperty(kScale, factor);
}

}  // namespace linkwright::ui
