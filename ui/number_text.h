#pragma once
// Numbers as the GUI shows them: the core's one number text (kinematics/model/number_text.h),
// as a QString. Its rule is the GUI's last guard of "never nan or inf": a value that is still
// not finite, whatever let it through, reads "undefined".

#include "kinematics/model/number_text.h"

#include <QString>

namespace linkwright::ui {

/// `value` with `precision` significant digits ('g') or decimals ('f'), as formatShort and
/// formatFixed write it; "undefined" if it is not finite.
inline QString numberText(double value, char format = 'g', int precision = 6) {
  return QString::fromStdString(format == 'f' ? kinematics::formatFixed(value, precision)
                                              : kinematics::formatShort(value, precision));
}

}  // namespace linkwright::ui
