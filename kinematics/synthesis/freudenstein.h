#pragma once
// Freudenstein's equation for the four-bar, in this repository's conventions (fourbar.h: O2 at
// the origin, O4 at (d, 0), crank O2→B at θ2, rocker O4→C at θ4, angles CCW from +x). The loop
// |C − B|² = b² with B = a·e(θ2), C = (d, 0) + c·e(θ4), expanded and divided by 2ac, reads
//   K1 cos θ4 − K2 cos θ2 + K3 = cos(θ2 − θ4),
//   K1 = d/a,  K2 = d/c,  K3 = (a² − b² + c² + d²) / 2ac,
// linear in K1, K2, K3. Three (θ2, θ4) pairs fix them exactly; more are fitted by linear least
// squares (the equation's residual, not the angle error, is minimised: Freudenstein's own
// approximation). Back from K, with d chosen: a = d/K1, c = d/K2, b² = a² + c² + d² − 2ac·K3.
// A negative a (or c) is a crank (rocker) of length |a| pointing the other way: the same
// linkage with that link's angle turned by π.

#include "kinematics/model/fourbar.h"
#include "kinematics/model/result.h"

#include <span>

namespace linkwright::kinematics {

struct FreudensteinCoefficients {
  double k1 = 0.0;
  double k2 = 0.0;
  double k3 = 0.0;
  bool operator==(const FreudensteinCoefficients&) const = default;
};

/// A required input and output angle: crank θ2 and rocker θ4 (rad, frame-relative).
struct AnglePair {
  double input = 0.0;
  double output = 0.0;
  bool operator==(const AnglePair&) const = default;
};

/// K1, K2, K3 from three pairs (exact) or more (least squares). Error (field "points") for
/// fewer than three pairs, a non-finite angle or a rank-deficient system (coincident or
/// degenerate pairs).
Result<FreudensteinCoefficients> freudensteinCoefficients(std::span<const AnglePair> pairs);

/// The residual K1 cos θ4 − K2 cos θ2 + K3 − cos(θ2 − θ4) at one pair.
double freudensteinResidual(const FreudensteinCoefficients& k, const AnglePair& pair);

/// The four-bar of K, with positive lengths, and which links point the other way.
struct FreudensteinLinkage {
  FourBarLengths lengths;
  bool crankReversed = false;   ///< a < 0: the crank's angle is θ2 + π
  bool rockerReversed = false;  ///< c < 0: the rocker's angle is θ4 + π
  bool operator==(const FreudensteinLinkage&) const = default;
};

/// The linkage with frame `frame` (length unit, > 0); Error (field "points") if K1 or K2 is 0
/// or not finite, or b² ≤ 0 (no real coupler).
Result<FreudensteinLinkage> freudensteinLinkage(const FreudensteinCoefficients& k, double frame);

}  // namespace linkwright::kinematics
