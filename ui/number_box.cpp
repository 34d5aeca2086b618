#include "ui/number_box.h"

namespace linkwright::ui {

NumberBox::NumberBox(QWidget* parent) : QDoubleSpinBox(parent) {}

void NumberBox::stepBy(int steps) {
  // Qt's adaptive step (a tenth of the value's leading digit) is Qt's to work out: its result
  // is rounded after. A plain step goes through setValue, which rounds to the decimals and
  // holds the range, after any text typed but not yet taken (keyboard tracking off), as Qt does.
  if (stepType() == AdaptiveDecimalStepType) {
    QDoubleSpinBox::stepBy(steps);
    setValue(value());
    return;
  }
  interpretText();
  setValue(value() + steps * singleStep());
  selectAll();
}

}  // namespace linkwright::ui
