#pragma once
// The drive and grid fields that every kind of design has (crank ω and α, the analysis
// grid), read and changed without caring which kind it is.

#include "kinematics/design/mechanism_design.h"

#include <variant>

namespace linkwright::ui {

/// A copy of `design` with `change` applied to whichever kind it holds; `change` takes
/// `auto&` and touches only the fields both kinds share (omega, alpha, fromDeg, toDeg, samples).
template <typename Change>
kinematics::Design withShared(kinematics::Design design, Change&& change) {
  std::visit([&](auto& d) { change(d); }, design);
  return design;
}

/// Crank speed (rad/s) and acceleration (rad/s²) of any design.
inline double designOmega(const kinematics::Design& d) {
  return std::visit([](const auto& x) { return x.omega; }, d);
}
inline double designAlpha(const kinematics::Design& d) {
  return std::visit([](const auto& x) { return x.alpha; }, d);
}
/// The analysis grid's ends, degrees.
inline double designFromDeg(const kinematics::Design& d) {
  return std::visit([](const auto& x) { return x.fromDeg; }, d);
}
inline double designToDeg(const kinematics::Design& d) {
  return std::visit([](const auto& x) { return x.toDeg; }, d);
}

}  // namespace linkwright::ui
