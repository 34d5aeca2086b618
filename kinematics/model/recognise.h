#pragma once
// What a linkage is, read from its structure rather than from how it was built or stored: a
// four-bar drawn point by point, or saved as a general linkage, is still a four-bar, and gets
// its Grashof class, exact crank range and limit positions (design/design_analysis.h).

#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/shaper.h"

#include <optional>

namespace linkwright::kinematics {

/// A mechanism that is a four-bar: a crank O2→B, an RRR joint C on B and a second ground
/// pivot O4, and nothing else but ground points and points fixed on the coupler.
struct FourBarStructure {
  FourBarLengths lengths;
  Branch branch = Branch::Open;  ///< in the four-bar's convention: open has C left of B→O4
  PointId o2, o4, b, c;
  double frameAngle = 0.0;  ///< direction O2→O4 (rad, CCW from +x)
  double crankPhase = 0.0;  ///< the crank's angle is the input angle plus this (rad)

  /// The input angle at which the crank makes `frameCrankAngle` with the frame line O2→O4.
  double inputAngle(double frameCrankAngle) const { return frameCrankAngle + frameAngle - crankPhase; }
};

/// Which points fixed on links a recogniser lets a linkage carry and still be the textbook
/// mechanism. What a four-bar is and does (its analysis, its named lengths, its instant centres)
/// does not depend on where its links carry points (a spring's end on the crank, say); its
/// cognates and coupler curve are of points on the coupler only.
enum class PointsOnLinks {
  CouplerOnly,  ///< a four-bar: on the coupler B–C (a slider-crank: on its rod B–C)
  AnyLink,      ///< on any of the mechanism's moving links
};

/// The mechanism's four-bar, if it is one. Safe on an unchecked mechanism (its lengths are
/// then as stored: checkFourBarLengths says whether they are valid).
std::optional<FourBarStructure> asFourBar(const Mechanism& mechanism,
                                          PointsOnLinks allowed = PointsOnLinks::CouplerOnly);

/// A mechanism that is a slider-crank: a crank O2→B and a slider C on B along a straight
/// ground guide, and nothing else but ground points and points fixed on its links.
struct SliderCrankStructure {
  PointId o2, b, c;
  double guideAngle = 0.0;  ///< the guide's direction (rad, CCW from +x)
};

/// The mechanism's slider-crank, if it is one. Safe on an unchecked mechanism.
std::optional<SliderCrankStructure> asSliderCrank(const Mechanism& mechanism,
                                                  PointsOnLinks allowed = PointsOnLinks::CouplerOnly);

/// A mechanism that is a quick-return shaper or Whitworth: a crank O2→B, a slotted rocker
/// through B about O4 ending at D, and a ram R on a horizontal ground guide, linked to D.
struct QuickReturnStructure {
  ShaperGeometry geometry;
  Branch ramBranch = Branch::Open;
};

/// The mechanism's quick return, if it is one (crank phase 0, as shaperQuickReturn assumes).
std::optional<QuickReturnStructure> asQuickReturn(const Mechanism& mechanism);

}  // namespace linkwright::kinematics
