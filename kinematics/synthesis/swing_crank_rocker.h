#pragma once
// Crank-rockers for a rocker swing ψ and a time ratio Q (the textbook limit-position method:
// as in Uicker, Pennock & Shigley, Norton, Waldron & Kinzel). At its two limit
// positions the rocker tip is at C1 and C2, |O4C1| = |O4C2| = c, ∠C1O4C2 = ψ, and the crank
// and coupler are in line: folded at C1 (|O2C1| = b − a), extended at C2 (|O2C2| = b + a). The
// crank turns π + α between them one way and π − α the other, so Q = (π + α)/(π − α) fixes
// α = π(Q − 1)/(Q + 1) = ∠C1O2C2: O2 lies on a circle through C1 and C2 on which the chord
// subtends α (on the line C1C2 extended when Q = 1). Then
//   a = (|O2C2| − |O2C1|)/2,  b = (|O2C2| + |O2C1|)/2,  d = |O2O4|.
//
// The family. In a frame with C1 = (−s, 0), C2 = (s, 0), s = c·sin(ψ/2), and O4 = (0, c·cos(ψ/2))
// on the chord's bisector, the mirror image about that bisector gives the same lengths, so we
// keep O2 on the C1 half. Two circles through C1, C2 see the chord at α (mirror images about
// the chord): O2 on the one beyond the chord from O4 (`parameter` < 0) or on the one on O4's
// side (`parameter` > 0); when Q = 1 both are the line C1C2 extended beyond C1. On either, O2 is
// placed by its distance from C1, r1 = |O2C1| = b − a, as |parameter| = r1 / (r1 + |C1C2|) in
// (0, 1). Only part of each curve gives a crank-rocker whose limits are C1 and C2: C1 and C2
// must lie on the same side of the frame line O2O4 (one assembly branch), the crank must turn
// fully and the rocker not. Those parts are found exactly by bisection on that test; near
// their ends the linkage degenerates (a change point: the worst transmission angle → 0).
//
// The built four-bar has its frame along +x (fourBarDesign); its branch is the side of the
// frame line that C1 and C2 lie on. The rocker's limit angles are reported in that frame.

#include "kinematics/design/synthesis_targets.h"
#include "kinematics/synthesis/candidate.h"

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// One crank-rocker of the family.
struct CrankRockerCandidate {
  double parameter = 0.0;  ///< its place on the family, in (−1, 1) (see above)
  FourBarLengths lengths;
  Branch branch = Branch::Open;
  double extendedCrankAngle = 0.0;   ///< crank angle at the extended limit (rad in [0, 2π), frame-relative)
  double foldedCrankAngle = 0.0;     ///< crank angle at the folded limit (rad in [0, 2π))
  double extendedRockerAngle = 0.0;  ///< rocker angle at C2 (rad in (−π, π], frame-relative)
  double foldedRockerAngle = 0.0;    ///< rocker angle at C1 (rad in (−π, π])
  /// design: the four-bar; error 0 (exact); minTransmission over the full turn.
  SynthesisCandidate candidate;
};

/// A range of the family parameter that gives crank-rockers, open at both ends.
struct ParameterRange {
  double from = 0.0;
  double to = 0.0;
  bool operator==(const ParameterRange&) const = default;
};

struct SwingSynthesis {
  std::vector<ParameterRange> valid;         ///< where the family gives crank-rockers
  std::vector<CrankRockerCandidate> family;  ///< spread evenly over `valid`, ordered by parameter
  /// The largest worst transmission angle among the crank-rockers whose longest / shortest
  /// link is within bounds.maxLinkRatio (all of them, if none is), refined by golden section.
  /// For Q = 1 it keeps improving as the linkage grows, towards 90° − ψ/2: the bound stops it.
  CrankRockerCandidate best;
};

/// Error naming the field ("swing", "timeRatio", "length") unless the target is valid.
std::optional<Error> checkSwingTarget(const SwingTarget& target);

/// The family's parameter ranges that give crank-rockers with the target's swing and ratio.
Result<std::vector<ParameterRange>> crankRockerRanges(const SwingTarget& target);

/// The crank-rocker at `parameter`; an Error (field "parameter") if it lies outside the
/// crank-rocker ranges or the linkage cannot be built.
Result<CrankRockerCandidate> crankRockerAt(const SwingTarget& target, double parameter,
                                           const DefectBounds& bounds = {});

/// `count` (≥ 1) crank-rockers spread over the family and the best one.
Result<SwingSynthesis> synthesiseCrankRocker(const SwingTarget& target, std::size_t count = 41,
                                             const DefectBounds& bounds = {});

}  // namespace linkwright::kinematics
