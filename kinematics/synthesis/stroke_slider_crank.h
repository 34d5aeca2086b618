#pragma once
// Offset slider-cranks for a stroke H and a time ratio Q, by the limit-position method
// (as in Norton and Uicker, Pennock & Shigley). At the ends of the stroke the crank and rod are
// in line: extended at C2 (|O2C2| = b + a), folded at C1 (|O2C1| = b − a), both on the guide
// at distance e (the offset) from O2, and C1C2 = H. The crank turns π ± α between them, so
// ∠C1O2C2 = α = π(Q − 1)/(Q + 1). The triangle O2C1C2 gives, with r1 = b − a, r2 = b + a:
//   H² = r1² + r2² − 2 r1 r2 cos α   (cosines),   r1 r2 sin α = H e   (twice its area),
// so (r2 − r1)² = H² − 2He·tan(α/2) and (r2 + r1)² = H² + 2He·cot(α/2):
//   a = ½ √(H² − 2He·tan(α/2)),   b = ½ √(H² + 2He·cot(α/2)).
// One free choice remains: the offset e (Q > 1; Q = 1 forces e = 0), or the rod b, giving
//   e = (4b² − H²)·tan(α/2) / 2H,   valid for H/2 < b < H / (2 sin(α/2)).
// Both ends must be reached on one branch: the slider sits beyond the crank pivot's foot on the
// guide at both, x1 = (4ab − H²)/2H > 0 (slider_crank.h's Open branch, guide along +x).
//
// The result is slider_crank.h's linkage: O2 at the origin, the guide along +x at height e.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/model/slider_crank.h"
#include "kinematics/synthesis/candidate.h"

#include <string>

namespace linkwright::kinematics {

struct SliderCrankSynthesis {
  SliderCrankGeometry geometry;
  double extendedCrankAngle = 0.0;  ///< crank angle at the stroke's far end C2 (rad in [0, 2π))
  double foldedCrankAngle = 0.0;    ///< crank angle at the near end C1 (rad in [0, 2π))
  double nearEnd = 0.0;             ///< x of C1 (length unit)
  double farEnd = 0.0;              ///< x of C2 = nearEnd + stroke
  /// design: the slider-crank; error 0 (exact); minTransmission: the worst over a turn of the
  /// angle between the rod and the guide's normal, π/2 − asin((a + |e|)/b).
  SynthesisCandidate candidate;
};

/// The slider-crank for the target; Error naming "stroke", "timeRatio", "rod" or "offset" if
/// the target is invalid or no slider-crank meets it (the message gives the valid range).
Result<SliderCrankSynthesis> synthesiseSliderCrank(const StrokeTarget& target, const DefectBounds& bounds = {});

}  // namespace linkwright::kinematics
