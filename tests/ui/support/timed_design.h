#pragma once
// Designs on a time base for the GUI tests: the thesis crank-rocker whose crank makes one
// cycloidal turn, 0 → 360° in 0.5 s (peak α 2πh/T² at T/4), and one that ramps to a speed at
// which it turns many times.

#include "kinematics/design/design.h"
#include "kinematics/model/units.h"

#include "tests/ui/support/four_bar_design.h"

namespace linkwright::testing {

inline constexpr double kRiseDuration = 0.5;  ///< s

/// The thesis crank-rocker, its crank on a cycloidal rise of one turn in kRiseDuration.
inline kinematics::Design cycloidalFourBar() {
  kinematics::Design d = fourBar();
  d.time =
      kinematics::TimeBase{kinematics::CycloidalRise{0.0, 2.0 * kinematics::kPi, kRiseDuration}, 0.0, kRiseDuration};
  return d;
}

/// The thesis crank-rocker ramping in 0.1 s to 10 turns per second, for 10 s: a hundred turns.
inline kinematics::Design longRampFourBar() {
  kinematics::Design d = fourBar();
  d.time = kinematics::TimeBase{kinematics::RampToSpeed{0.0, 20.0 * kinematics::kPi, 0.1}, 0.0, 10.0};
  return d;
}

}  // namespace linkwright::testing
