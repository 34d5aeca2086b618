#pragma once
// The unit the plots show angles in. It applies to everything angular on the plots: the crank
// angle on the x axis, link and transmission angles, ω (unit/s) and α (unit/s²). The core
// works in radians (SweepResult); the conversion happens here, at the edge, through units.h.

#include "kinematics/model/units.h"

#include <QCoreApplication>
#include <QString>

namespace linkwright::ui {

enum class AngleUnit { Degrees, Radians };

/// An angle, angular velocity or acceleration given in rad (per s, per s²) in `unit`.
constexpr double toAngleUnit(double radians, AngleUnit unit) {
  return unit == AngleUnit::Degrees ? kinematics::radToDeg(radians) : radians;
}

/// The inverse of toAngleUnit.
constexpr double fromAngleUnit(double value, AngleUnit unit) {
  return unit == AngleUnit::Degrees ? kinematics::degToRad(value) : value;
}

/// The unit's symbol as written in axis titles: "deg" or "rad" (as in the CSV column names).
inline QString angleUnitSymbol(AngleUnit unit) {
  return unit == AngleUnit::Degrees ? QCoreApplication::translate("AngleUnit", "deg")
                                    : QCoreApplication::translate("AngleUnit", "rad");
}

}  // namespace linkwright::ui
