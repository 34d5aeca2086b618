#pragma once
// Crank-shapers (crank and slotted lever quick return) for a ram stroke H and a time ratio Q
// (as in Uicker, Pennock & Shigley and Norton). The lever stops where its slot is tangent to
// the crank circle (quick_return.h), so with crank r and pivots d apart it swings through
// 2·asin(r/d) while the crank turns π ± 2·asin(r/d): Q = (π + α)/(π − α) gives r/d = sin(α/2)
// and a lever swing of α. We put O4 straight below O2 (O4 = (0, −d)), so the lever swings
// symmetrically about +y. With lever length R its tip D is at O4 + R·(∓sin(α/2), cos(α/2)) at
// the limits: at equal heights, so whatever the link D→R and the guide height, the ram moves
// between them exactly the distance the tip does, 2R·sin(α/2) = H. So
//   d = r / sin(α/2),   R = H / (2 sin(α/2)),
// with the crank r the free choice. The lever must reach past the crank pin at every angle,
// R > d + r, i.e. r < H / (2 (1 + sin(α/2))). The guide goes by default at the mid-height of
// the tip's arc, −d + R·(1 + cos(α/2))/2, where the link tilts least; the link must bridge the
// guide and the tip everywhere on that arc. Q = 1 has no crank-shaper (d would be infinite).
//
// The result is shaper.h's linkage: O2 at the origin, the ram's guide horizontal.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/model/shaper.h"
#include "kinematics/synthesis/candidate.h"

#include <optional>
#include <string>

namespace linkwright::kinematics {

struct ShaperSynthesis {
  ShaperGeometry geometry;
  /// design: the shaper; error 0 (exact); minTransmission: the worst over the lever's swing
  /// of the angle between the link D→R and the guide's normal.
  SynthesisCandidate candidate;
};

/// The crank-shaper for the target; Error naming "stroke", "timeRatio", "crank", "link" or
/// "guideHeight" if the target is invalid or no shaper meets it (the message gives the range).
Result<ShaperSynthesis> synthesiseShaper(const ShaperTarget& target, const DefectBounds& bounds = {});

}  // namespace linkwright::kinematics
