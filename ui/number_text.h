#pragma once
// Numbers as the GUI shows them: the core's one number text (kinematics/model/number_text.h),
// as a QString. Its rule is the GUI's last guard of "never nan or inf": a value that is still
// not finite, whatever let it through, reads "undefined".

#include "kinematics/model/number_text.h"

#include <QString>

#include <algorithm>
#include <cmath>

namespace linkwright::ui {

/// `value` with `precision` significant digits ('g') or decimals ('f'), as formatShort and
/// formatFixed write it; "undefined" if it is not finite.
inline QString numberText(double value, char format = 'g', int precision = 6) {
  return QString::fromStdString(format == 'f' ? kinematics::formatFixed(value, precision)
                                              : kinematics::formatShort(value, precision));
}

/// A point as "(x, y)" with `significant` digits. A coordinate smaller than the larger one's
/// last printed digit is round-off of the solver, not a position, and reads 0: "(30, 0)", not
/// "(30, 2.548e-15)".
inline QString pointText(double x, double y, int significant = 6) {
  const double resolution = std::max(std::abs(x), std::abs(y)) * std::pow(10.0, -significant);
  const auto shown = [resolution](double c) { return std::abs(c) < resolution ? 0.0 : c; };
  return QStringLiteral("(%1, %2)").arg(numberText(shown(x), 'g', significant), numberText(shown(y), 'g', significant));
}

}  // namespace linkwright::ui
