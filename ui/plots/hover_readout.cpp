#include "ui/plots/hover_readout.h"

#include "ui/number_text.h"

#include <QCursor>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

QString formatReadoutNumber(double value) {
  const double magnitude = std::abs(value);
  const int leading = magnitude > 0.0 ? static_cast<int>(std::floor(std::log10(magnitude))) : 0;
  const int decimals = std::clamp(2 - leading, 1, 6);
  return numberText(value, 'f', decimals);
}

QString readoutText(const PlotCurve& curve, QPointF point, AngleUnit unit, const QString& lengthUnit,
                    const PlotXAxis& x) {
  const QuantityKind kind = quantityKind(curve.quantity);
  // Degrees read best with the degree sign right after the number, as in "at crank 90.0°".
  const bool degreeSign = unit == AngleUnit::Degrees;
  const QString valueUnit = quantityUnit(curve.quantity, unit, lengthUnit);  // none for a four-bar's ratios
  const QString value = kind == QuantityKind::Angle && degreeSign ? formatReadoutNumber(point.y()) + QStringLiteral("°")
                        : valueUnit.isEmpty()                     ? formatReadoutNumber(point.y())
                                              : formatReadoutNumber(point.y()) + QLatin1Char(' ') + valueUnit;
  return HoverReadout::tr("%1 = %2 at %3").arg(curve.name, value, xReadoutText(point.x(), x, unit));
}

HoverReadout::HoverReadout(QWidget* parent) : QLabel(parent) {
  setObjectName(QStringLiteral("hover_readout"));
  setTextInteractionFlags(Qt::TextSelectableByMouse);
  clearPoint();
}

void HoverReadout::showPoint(const PlotCurve& curve, QPointF point, AngleUnit unit, const QString& lengthUnit,
                             bool inside, const PlotXAxis& x) {
  showText(inside ? readoutText(curve, point, unit, lengthUnit, x) : QString(), inside);
}

void HoverReadout::showText(const QString& text, bool inside) {
  if (!inside) {
    clearPoint();
    QToolTip::hideText();
    return;
  }
  setText(text);
  QToolTip::showText(QCursor::pos(), text, this);
}

void HoverReadout::clearPoint() { setText(tr("Point at a curve to read its value.")); }

}  // namespace linkwright::ui
