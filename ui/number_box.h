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
};

}  // namespace linkwright::ui
