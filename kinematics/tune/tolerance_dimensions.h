#pragma once
// The dimensions a tolerance applies to, each in the linkage's length unit: every length and
// coordinate among a linkage's parameters (parameters.h: a four-bar's named lengths, pivots'
// x and y, a point's offsets on its link, guides' and paths' points, constraint lengths), and
// for a recognised four-bar O4's place across the frame line (O4 moved at right angles to
// the nominal frame line O2→O4, where the editor has the frame's direction), so that ± on
// every pivot moves O4 both ways. Angles that are not a pivot's place (a crank's phase, a guide's angle, an arc's start
// and sweep) and free points' guesses (not dimensions: where Newton starts) are not listed.
// The tolerance analyses (tolerance_sensitivity.h, tolerance_monte_carlo.h) both read these,
// so the sensitivities and the Monte-Carlo samples are about the same numbers.

#include "kinematics/design/parameters.h"
#include "kinematics/model/mechanism.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

struct ToleranceDimension {
  Parameter parameter;
  std::string name;    ///< "coupler length", "O2 x", "B–C length", "O4 across the frame line"
  double value = 0.0;  ///< nominal, length unit (0 for O4 across the frame line)
  bool operator==(const ToleranceDimension&) const = default;
};

/// The dimensions of `mechanism`, in parametersOf's order. Assumes checkMechanism passed.
std::vector<ToleranceDimension> toleranceDimensions(const Mechanism& mechanism);

/// `mechanism` with each dimension moved from its nominal by offsets[d] (length unit);
/// offsets.size() == dimensions.size(). A four-bar's named lengths are set first (they
/// place O4 from the nominal O2), then the raw numbers, so each offset moves its own number
/// alone: O2's x moves O2, not O4.
Mechanism offsetDimensions(const Mechanism& mechanism, const std::vector<ToleranceDimension>& dimensions,
                           const std::vector<double>& offsets);

/// `mechanism` whose every number exceeds `mechanism`'s by that number's derivative with
/// respect to `dimension` (per length unit): what differentiatePose (analysis/pose_jet.h)
/// reads. The numbers are affine in every dimension, so a unit step is the derivative.
Mechanism steppedMechanism(const Mechanism& mechanism, const ToleranceDimension& dimension);

}  // namespace linkwright::kinematics
