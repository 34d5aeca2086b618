#pragma once
// Four-bar designs for the GUI tests, on the one Design: a four-bar by its lengths, a design's
// four-bar lengths read back, and a design with other lengths (as the dimensions panel edits).

#include "kinematics/design/design.h"
#include "kinematics/design/fourbar_dimensions.h"
#include "kinematics/model/recognise.h"

namespace linkwright::testing {

/// makeFourBar's four-bar (O2 at the origin, O4 on +x), ω = 1 rad/s, 721 samples.
inline kinematics::Design fourBar(const kinematics::FourBarLengths& lengths = kinematics::kThesisCrankRocker,
                                  kinematics::Branch branch = kinematics::Branch::Open) {
  return kinematics::fourBarDesign(lengths, branch).value();
}

/// The lengths of the four-bar `design` holds (it must hold one).
inline kinematics::FourBarLengths lengthsOf(const kinematics::Design& design) {
  return kinematics::asFourBar(design.mechanism).value().lengths;
}

/// `design` (a four-bar) with other lengths.
inline kinematics::Design withLengths(kinematics::Design design, const kinematics::FourBarLengths& lengths) {
  const auto s = kinematics::asFourBar(design.mechanism).value();
  design.mechanism = kinematics::withFourBarLengths(design.mechanism, s, lengths);
  return design;
}

}  // namespace linkwright::testing
