#pragma once
// The masses and loads of either kind of design (FourBarDesign::dynamics,
// MechanismDesign::dynamics), read and replaced without caring which kind it is.

#include "kinematics/design/mechanism_design.h"
#include "kinematics/dynamics/mass_properties.h"

#include <variant>

namespace linkwright::ui {

/// The design's masses, centres, inertias and loads (empty: none given).
inline const kinematics::LinkageDynamics& designDynamics(const kinematics::Design& design) {
  return std::visit([](const auto& d) -> const kinematics::LinkageDynamics& { return d.dynamics; }, design);
}

/// A copy of `design` with `change` applied to its dynamics; `change` takes
/// `kinematics::LinkageDynamics&`.
template <typename Change>
kinematics::Design withDynamics(kinematics::Design design, Change&& change) {
  std::visit([&](auto& d) { change(d.dynamics); }, design);
  return design;
}

}  // namespace linkwright::ui
