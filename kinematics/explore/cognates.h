#pragma once
// Roberts–Chebyshev cognates: the two other four-bars whose coupler point traces the same curve
// as a four-bar's coupler point P (Roberts 1875, Chebyshev 1878; Hartenberg & Denavit,
// Kinematic Synthesis of Linkages, 1964; Norton, Design of Machinery, §3.9).
//
// Derivation. Points are complex numbers in the plane; labels as fourbar.h: ground pivots O2
// (crank) and O4 (rocker), crank tip B, coupler–rocker joint C (Norton's O_A, O_B, A, B). The
// links as vectors: crank a = B − O2 (angle θ2), coupler b = C − B (θ3), rocker c = C − O4
// (θ4), frame d = O4 − O2; the loop is a + b = d + c. The coupler is rigid, so P's place on
// it is one complex constant z = (P − B)/(C − B), and P = O2 + a + z b. The third pivot is
//   O6 = O2 + z d          (triangle O2 O4 O6 is similar to B C P: Cayley's diagram).
// Cognate 1, pivots O2 and O6: P − O2 = z b + a, and with the loop P − O6 = z b + a − z d =
// a + z c. So its crank O2→B1 is z b (turns with θ3), its coupler B1→C1 is z a (with θ2), its
// rocker O6→C1 is z c (with θ4), and P = B1 + a = B1 + (C1 − B1)/z:
//   B1 = O2 + z (C − B),  C1 = O6 + z (C − O4);  loop z b + z a = z d + z c (z times the original).
// Cognate 2, pivots O6 and O4: P − O6 = (1 − z) a + z c and P − O4 = c + (z − 1) b. So its
// crank O6→B2 is (1 − z) a (turns with θ2), its rocker O4→C2 is (z − 1) b (with θ3), its
// coupler B2→C2 is (z − 1) c (with θ4), and P = B2 + z c = B2 + z/(z − 1) (C2 − B2):
//   B2 = O6 + (1 − z)(B − O2),  C2 = O4 + (z − 1)(C − B);  loop (1 − z)(a − c) = (1 − z)(d − b).
// Each cognate link is a fixed complex multiple of an original link, so it keeps its length
// (cognate 1 is the original scaled by |z| with crank and coupler swapped, cognate 2 scaled by
// |1 − z| with coupler and rocker swapped) and turns with that link: its ω is that link's ω.
// The three move together when cognate 2's crank turns at the original crank's ω (a constant
// speed, 1:1) and cognate 1's crank at the original coupler's ω3, which varies over the cycle.
// z = 0 (P at B) shrinks cognate 1 to a point, z = 1 (P at C) cognate 2: no cognate there.
//
// Building a cognate as a design: each is a four-bar as makeFourBar names it (points O2, O4,
// B, C, P; links crank, coupler, rocker), constructed at the original's pose at its grid's first
// sample q0 (the cycle's start). Its crank phase is the crank's angle there less q0, so its input
// at that pose is q0 too: cognate 2's input is then the original's at every instant (same grid,
// speed and time base); cognate 1's is θ3 less a constant, over the range θ3 sweeps in the cycle
// (a full turn when the coupler turns fully). Its branch is the one whose joint C lands where the
// construction put it.

#include "kinematics/analysis/grashof.h"
#include "kinematics/design/design.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <optional>
#include <string>

namespace linkwright::kinematics {

/// A four-bar's joints at one pose, labelled as fourbar.h (length unit, world frame).
struct FourBarJoints {
  Eigen::Vector2d o2 = Eigen::Vector2d::Zero();  ///< crank pivot
  Eigen::Vector2d o4 = Eigen::Vector2d::Zero();  ///< rocker pivot
  Eigen::Vector2d b = Eigen::Vector2d::Zero();   ///< crank tip, the crank–coupler joint
  Eigen::Vector2d c = Eigen::Vector2d::Zero();   ///< the coupler–rocker joint
  Eigen::Vector2d p = Eigen::Vector2d::Zero();   ///< the coupler point
};

/// The cognates' joints at one pose of the original (the derivation above).
struct CognateJoints {
  Eigen::Vector2d thirdPivot = Eigen::Vector2d::Zero();  ///< O6 = O2 + z (O4 − O2), length unit
  FourBarJoints first;                                   ///< cognate 1: O2, O6, B1, C1, P
  FourBarJoints second;                                  ///< cognate 2: O6, O4, B2, C2, P
};

/// P's place on the coupler, z = (P − B)/(C − B) as a complex number (dimensionless): its real
/// part along B→C in coupler lengths, its imaginary part 90° counter-clockwise from it. Needs
/// B ≠ C.
std::complex<double> couplerRatio(const FourBarJoints& joints);

/// The cognates' joints at the original's pose `joints` (exact: complex products, no solve).
CognateJoints cognateJoints(const FourBarJoints& joints);

/// A link of the original four-bar, that a cognate's link turns with.
enum class OriginalLink { Crank, Coupler, Rocker };

/// "crank", "coupler", "rocker".
std::string_view toString(OriginalLink link);

/// One of the three four-bars (the original or a cognate) and its figures over the original's
/// cycle (the original's grid or time base, at least 721 and at most kMaxTurnSamples samples).
struct CognateFourBar {
  Design design;             ///< a cognate: points O2, O4, B, C, P, links crank, coupler, rocker
  FourBarStructure fourBar;  ///< its recognised four-bar (lengths in the length unit)
  Eigen::Vector2d crankPivot = Eigen::Vector2d::Zero();   ///< O2, length unit
  Eigen::Vector2d rockerPivot = Eigen::Vector2d::Zero();  ///< O4, length unit
  /// The original's link that its crank, coupler and rocker each turn with (same ω).
  std::array<OriginalLink, 3> turnsWith{OriginalLink::Crank, OriginalLink::Coupler, OriginalLink::Rocker};
  GrashofReport grashof;  ///< of its lengths (grashof.h)
  /// The worst min(μ, π − μ) of its transmission angle over the motion it makes in the cycle
  /// (rad, transmission.h); none where that motion cannot be followed exactly.
  std::optional<double> worstTransmission;
  /// Its crank's ω over the original crank's ω at the cycle's samples where both are defined and
  /// the original's crank moves (dimensionless): 1 for a crank that turns with the original's
  /// crank; the original coupler's ω3/ω2, least and greatest, for one that turns with the
  /// coupler (none if no sample had both).
  std::optional<double> crankSpeedRatioMin = 1.0;
  std::optional<double> crankSpeedRatioMax = 1.0;
};

/// A four-bar and its two cognates.
struct CognateSet {
  std::string couplerPoint;                              ///< the name of the original's point that is traced
  std::complex<double> z;                                ///< couplerRatio at the constructed pose (dimensionless)
  Eigen::Vector2d thirdPivot = Eigen::Vector2d::Zero();  ///< O6, length unit
  double constructedAt = 0.0;                            ///< the original's input q0 where they are built (rad)
  CognateFourBar original;                               ///< the design as given, with its figures
  std::array<CognateFourBar, 2> cognates;                ///< cognate 1 (pivots O2, O6), cognate 2 (O6, O4)
};

/// The cognates of `original`'s coupler point named `couplerPoint` (default: its first point
/// fixed on the coupler). Errors as sentences: checkDesign's; not a four-bar
/// (InvalidStructure, field "mechanism"); no point on the coupler, or none of that name there,
/// or P at B or at C, so that a cognate has links of zero length, or a cognate beyond the
/// lengths a linkage may have (InvalidValue, field "couplerPoint"); the original or a cognate
/// not assembled at the cycle's start (NotAssemblable, field "design").
Result<CognateSet> cognates(const Design& original, const std::optional<std::string>& couplerPoint = std::nullopt);

}  // namespace linkwright::kinematics
