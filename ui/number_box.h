#pragma once
// The designer's number field: a QDoubleSpinBox whose arrow keys, buttons and wheel land on the
// values it shows. Qt adds the step to the stored value without rounding it to the box's
// decimals, so 1.3 stepped down by 1 holds 0.30000000000000004 while it shows "0.30", and the
// core's refusal then quoted the round-off back ("got 0.30000000000000004"). Typed values are
// rounded by Qt already; a step now goes through the same rounding.

#include <QDoubleSpinBox>

namespace linkwright::ui {

class NumberBox : public QDoubleSpinBox {
  Q_OBJECT
public:
  explicit NumberBox(QWidget* parent = nullptr);

  void stepBy(int steps) override;
  /// Qt sizes a spin box for the longest text its range allows: ±1e9 N·m with four decimals
  /// took 150 px and pushed the Forces tab's loads past a projector's narrow side column. The
  /// least width here is for the text shown or a five-digit value with the decimals and the
  /// suffix, whichever is wider (never more than Qt's); a longer number scrolls in the field.
  QSize minimumSizeHint() const override;
};

}  // namespace linkwright::ui
