#include "ui/number_box.h"

#include <QFontMetrics>
#include <QLineEdit>

#include <algorithm>

namespace linkwright::ui {

NumberBox::NumberBox(QWidget* parent) : QDoubleSpinBox(parent) {
  // Qt's spin box never shrinks below its size hint (QSizePolicy::Minimum): it may, down to
  // minimumSizeHint, where a column is narrow.
  setSizePolicy(QSizePolicy::Preferred, sizePolicy().verticalPolicy());
}

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

QSize NumberBox::minimumSizeHint() const {
  const QSize qt = QDoubleSpinBox::minimumSizeHint();
  const QFontMetrics metrics(font());
  // Qt's hint is its longest text (each bound's, cut to 18 characters, with the prefix, the
  // suffix and a space) plus the frame, the buttons and the cursor: the same less that text.
  const QString fixed = prefix() + suffix() + QLatin1Char(' ');
  const auto widthOf = [&](const QString& text) { return metrics.horizontalAdvance(text); };
  int longest = 0;
  for (const double bound : {minimum(), maximum()}) {
    QString text = textFromValue(bound);
    text.truncate(18);
    longest = std::max(longest, widthOf(text + fixed));
  }
  if (!specialValueText().isEmpty()) longest = std::max(longest, widthOf(specialValueText()));
  const QString typical = QStringLiteral("-00000") + (decimals() > 0 ? QStringLiteral(".") : QString()) +
                          QString(decimals(), QLatin1Char('0'));
  const int wanted = std::max(widthOf(typical + fixed), widthOf(lineEdit()->text() + QLatin1Char(' ')));
  return {std::min(qt.width(), qt.width() - longest + wanted), qt.height()};
}

}  // namespace linkwright::ui
