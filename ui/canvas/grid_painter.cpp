#include "ui/canvas/grid_painter.h"

#include "ui/number_text.h"

#include "ui/canvas/canvas_style.h"

#include <QCoreApplication>
#include <QFontMetricsF>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

double gridSpacing(double pixelsPerUnit, double minPixels) {
  if (!(pixelsPerUnit > 0.0) || !std::isfinite(pixelsPerUnit) || !(minPixels > 0.0)) return 1.0;
  const double least = minPixels / pixelsPerUnit;  // model units
  const double decade = std::pow(10.0, std::floor(std::log10(least)));
  for (const double step : {1.0, 2.0, 5.0, 10.0}) {
    // A relative tolerance keeps an exact 40 px (decade·step) from being skipped by rounding.
    if (step * decade >= least * (1.0 - 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

QString formatGridValue(double value, double spacing) {
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(spacing) + 1e-9)));
  if (std::abs(value) < 0.5 * spacing) value = 0.0;  // no "-0"
  return numberText(value, 'f', decimals);
}

namespace {

void drawLines(QPainter* painter, const QRectF& exposed, double spacing) {
  QPen minor(colors().grid, 1.0);
  minor.setCosmetic(true);
  QPen axis(colors().gridAxis, colors().gridAxisWidthPx);
  axis.setCosmetic(true);
  const double x0 = std::ceil(exposed.left() / spacing);
  const double y0 = std::ceil(exposed.top() / spacing);
  for (double i = x0; i * spacing <= exposed.right(); i += 1.0) {
    painter->setPen(i == 0.0 ? axis : minor);
    painter->drawLine(QPointF(i * spacing, exposed.top()), QPointF(i * spacing, exposed.bottom()));
  }
  for (double i = y0; i * spacing <= exposed.bottom(); i += 1.0) {
    painter->setPen(i == 0.0 ? axis : minor);
    painter->drawLine(QPointF(exposed.left(), i * spacing), QPointF(exposed.right(), i * spacing));
  }
}

// Numbers in device pixels, so they read upright whatever the view's y flip. The x numbers
// keep clear of the y numbers' column and of the caption in the bottom-right corner.
void drawLabels(QPainter* painter, const QRectF& visible, double spacing, const QString& unit, double textScale) {
  const QTransform toDevice = painter->worldTransform();
  const QRectF device = toDevice.mapRect(visible);
  painter->save();
  painter->resetTransform();
  QFont font = painter->font();
  font.setPointSizeF(8.0 * textScale);
  painter->setFont(font);
  painter->setPen(colors().gridLabel);
  const QFontMetricsF metrics(font);
  const double margin = 3.0 * textScale;
  const double baseline = device.bottom() - margin - metrics.descent();

  double column = 0.0;  // width of the y numbers
  for (double i = std::ceil(visible.top() / spacing); i * spacing <= visible.bottom(); i += 1.0) {
    const double y = toDevice.map(QPointF(0.0, i * spacing)).y();
    if (y < device.top() + metrics.height() || y > device.bottom() - 2.0 * metrics.height()) continue;
    const QString text = formatGridValue(i * spacing, spacing);
    painter->drawText(QPointF(device.left() + margin, y - margin), text);
    column = std::max(column, metrics.horizontalAdvance(text));
  }
  const QString caption =
      QCoreApplication::translate("LinkageView", "grid %1 %2").arg(formatGridValue(spacing, spacing), unit);
  const double captionLeft = device.right() - margin - metrics.horizontalAdvance(caption);
  painter->drawText(QPointF(captionLeft, baseline), caption);
  for (double i = std::ceil(visible.left() / spacing); i * spacing <= visible.right(); i += 1.0) {
    const double x = toDevice.map(QPointF(i * spacing, 0.0)).x();
    const QString text = formatGridValue(i * spacing, spacing);
    if (x < device.left() + column + 3.0 * margin ||
        x + margin + metrics.horizontalAdvance(text) > captionLeft - 2.0 * margin)
      continue;
    painter->drawText(QPointF(x + margin, baseline), text);
  }
  painter->restore();
}

}  // namespace

void paintGrid(QPainter* painter, const QRectF& exposed, const QRectF& visible, const QString& unit, double textScale) {
  const double pixelsPerUnit = std::abs(painter->worldTransform().m11());
  const double spacing = gridSpacing(pixelsPerUnit);
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing, false);  // crisp one-pixel lines
  drawLines(painter, exposed, spacing);
  painter->restore();
  drawLabels(painter, visible, spacing, unit, textScale);
}

}  // namespace linkwright::ui
