#pragma once
// Six-bar linkages solvable by dyads: a driving four-bar (O2, B, C, O4 as in fourbar.h) and one
// more RRR dyad, links 5 and 6 meeting at joint E. Which links carry the dyad decides the
// type (the Watt chain has its two ternary links joined, the Stephenson chain does not):
//
//   Watt I         ground binary; link 5 from P on the coupler, link 6 from D on the rocker
//                  (coupler and rocker are the ternaries, joined at C)
//   Watt II        ground ternary (O2, O4, O6); link 5 from P on the rocker, link 6 from O6
//   Stephenson I   ground binary; link 5 from P on the crank, link 6 from D on the rocker
//   Stephenson III ground ternary (O2, O4, O6); link 5 from P on the coupler, link 6 from O6
//
// (Stephenson II and a Stephenson III driven from link 6 need the Newton solver: no dyad
// order exists. See sixbar_newton.h.)

#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

enum class SixBarKind { WattI, WattII, StephensonI, StephensonIII };

/// Dimensions of a dyad six-bar, one length unit.
struct SixBarGeometry {
  SixBarKind kind = SixBarKind::WattI;
  FourBarLengths fourBar;  ///< the driving four-bar, frame along +x from O2
  Branch fourBarBranch = Branch::Open;
  CouplerPointSpec first;                                 ///< P, where link 5 starts, on its link's frame (fourbar.h)
  CouplerPointSpec second;                                ///< D on the rocker (Watt I, Stephenson I); else unused
  Eigen::Vector2d groundPivot = Eigen::Vector2d::Zero();  ///< O6 (Watt II, Stephenson III); else unused
  double link5 = 0.0;                                     ///< P to E
  double link6 = 0.0;                                     ///< D (or O6) to E
  Branch dyadBranch = Branch::Open;                       ///< E's branch, with P as the dyad's first point
  bool operator==(const SixBarGeometry&) const = default;
};

/// "watt-i", "watt-ii", "stephenson-i", "stephenson-iii".
std::string sixBarKindName(SixBarKind kind);

/// Builds points O2, O4, B, C, P, then D or O6, then E; links crank, coupler, rocker, link5
/// (P→E), link6 (D→E or O6→E). Errors name the field ("link5", "first.along", …).
Result<Mechanism> makeSixBar(const SixBarGeometry& geometry, const std::string& lengthUnit = "mm");

}  // namespace linkwright::kinematics
