#pragma once
// The read-out of the curve under the mouse: "rocker ω4 = 0.619 rad/s at crank 90.0°" (or
// "at t = 0.250 s" on a time axis), shown in a line under the charts and as a tool tip at the
// mouse.

#include "ui/plots/angle_unit.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/plot_x_axis.h"

#include <QLabel>
#include <QPointF>

namespace linkwright::ui {

/// `value` with about three significant digits (at least one decimal, at most six).
QString formatReadoutNumber(double value);
/// The read-out sentence for `point` (x on `x`, a crank angle by default; y = value, in plot
/// units) on `curve`.
QString readoutText(const PlotCurve& curve, QPointF point, AngleUnit unit,
                    const QString& lengthUnit = QStringLiteral("mm"), const PlotXAxis& x = {});

class HoverReadout : public QLabel {
  Q_OBJECT
public:
  explicit HoverReadout(QWidget* parent = nullptr);

  /// Shows the read-out of `curve` at `point`, or the idle hint if `inside` is false.
  void showPoint(const PlotCurve& curve, QPointF point, AngleUnit unit, const QString& lengthUnit, bool inside,
                 const PlotXAxis& x = {});
  /// Shows `text` (another tool's row under the mouse), or the idle hint if `inside` is false.
  void showText(const QString& text, bool inside);
  /// Back to the idle hint.
  void clearPoint();
};

}  // namespace linkwright::ui
