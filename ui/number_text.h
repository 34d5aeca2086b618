#pragma once
// Numbers as the GUI shows them. The last guard of the "never nan or inf" promise: a value
// that is still not finite, whatever let it through, reads "undefined", never "nan" or "inf".

#include <QCoreApplication>
#include <QString>

#include <cmath>

namespace linkwright::ui {

/// `value` in QString::number's `format` and `precision`, or "undefined" if it is not finite.
inline QString numberText(double value, char format = 'g', int precision = 6) {
  if (!std::isfinite(value)) return QCoreApplication::translate("NumberText", "undefined");
  return QString::number(value, format, precision);
}

}  // namespace linkwright::ui
