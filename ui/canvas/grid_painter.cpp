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

}  // namespace

QFont gridLabelFont(QFont font, double textScale) {
  font.setPointSizeF(8.0 * textScale);
  return font;
}

// Numbers in device pixels, so they read upright whatever the view's y flip. The x numbers
// keep clear of the y numbers' column and of the caption in the bottom-right corner, and of
// each other: a number only every `every` lines (1, 2, 5, 10…), the fewest that leave one
// digit's room between the widest two.
std::vector<GridLabel> gridLabels(const QTransform& toDevice, const QRectF& visible, double spacing,
                                  const QString& unit, const QFont& font, double textScale) {
  std::vector<GridLabel> out;
  const QRectF device = toDevice.mapRect(visible);
  const QFontMetricsF metrics(font);
  const double margin = 3.0 * textScale;
  const double baseline = device.bottom() - margin - metrics.descent();
  const auto add = [&](const QPointF& at, const QString& text) {
    out.push_back(
        {at, text, QRectF(at.x(), at.y() - metrics.ascent(), metrics.horizontalAdvance(text), metrics.height())});
  };

  double column = 0.0;  // width of the y numbers
  for (double i = std::ceil(visible.top() / spacing); i * spacing <= visible.bottom(); i += 1.0) {
    const double y = toDevice.map(QPointF(0.0, i * spacing)).y();
    if (y < device.top() + metrics.height() || y > device.bottom() - 2.0 * metrics.height()) continue;
    const QString text = formatGridValue(i * spacing, spacing);
    add(QPointF(device.left() + margin, y - margin), text);
    column = std::max(column, metrics.horizontalAdvance(text));
  }
  const QString caption =
      QCoreApplication::translate("LinkageView", "grid %1 %2").arg(formatGridValue(spacing, spacing), unit);
  const double captionLeft = device.right() - margin - metrics.horizontalAdvance(caption);
  add(QPointF(captionLeft, baseline), caption);

  const double first = std::ceil(visible.left() / spacing), last = std::floor(visible.right() / spacing);
  const double widest = std::max(metrics.horizontalAdvance(formatGridValue(first * spacing, spacing)),
                                 metrics.horizontalAdvance(formatGridValue(last * spacing, spacing)));
  const double linePx = spacing * std::abs(toDevice.m11());
  const double digit = metrics.horizontalAdvance(QStringLiteral("0"));
  const double room = widest + digit;
  double every = 1.0;
  for (double decade = 1.0; linePx > 0.0 && every * linePx < room && decade < 1e9; decade *= 10.0)
    for (const double step : {1.0, 2.0, 5.0})
      if (every * linePx < room) every = step * decade;
  for (double i = first; i <= last; i += 1.0) {
    if (std::fmod(std::abs(i), every) != 0.0) continue;
    const double x = toDevice.map(QPointF(i * spacing, 0.0)).x();
    const QString text = formatGridValue(i * spacing, spacing);
    if (x < device.left() + column + 3.0 * margin || x + margin + metrics.horizontalAdvance(text) > captionLeft - digit)
      continue;
    add(QPointF(x + margin, baseline), text);
  }
  return out;
}

void paintGrid(QPainter* painter, const QRectF& exposed, const QRectF& visible, const QString& unit, double textScale) {
  const double pixelsPerUnit = std::abs(painter->worldTransform().m11());
  const double spacing = gridSpacing(pixelsPerUnit);
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing, false);  // crisp one-pixel lines
  drawLines(painter, exposed, spacing);
  painter->restore();
  const QFont font = gridLabelFont(painter->font(), textScale);
  const std::vector<GridLabel> labels = gridLabels(painter->worldTransform(), visible, spacing, unit, font, textScale);
  painter->save();
  painter->resetTransform();
  painter->setFont(font);
  painter->setPen(colors().gridLabel);
  for (const GridLabel& label : labels) painter->drawText(label.at, label.text);
  painter->restore();
}

}  // namespace linkwright::ui
