#pragma once
// Transmission angle μ of a four-bar: the angle at C between the coupler and the rocker
// (the thesis's γ, seed 000 eq. (5)):  cos μ = (b² + c² − BD²) / 2bc,  μ ∈ [0°, 180°].
// μ depends on θ only through the diagonal BD, which is monotonic in cos θ, so its extremes
// over the cycle occur at θ = 0, θ = 180° or at the edges of the assemblable range: found
// exactly, not by sampling. Designers keep μ within about 40°–140°.

#include "kinematics/model/fourbar.h"

#include <optional>

namespace linkwright::kinematics {

struct TransmissionRange {
  double minimum = 0.0;         ///< rad
  double minimumAtCrank = 0.0;  ///< crank angle (rad, in [0, π]) where μ is smallest
  double maximum = 0.0;         ///< rad
  double maximumAtCrank = 0.0;  ///< crank angle (rad, in [0, π]) where μ is largest
  double worstDeviation = 0.0;  ///< max |μ − 90°| over the cycle, rad
  bool operator==(const TransmissionRange&) const = default;
};

/// The transmission angle at crank angle `crankAngle` (rad), or nullopt if it cannot be assembled.
std::optional<double> fourBarTransmissionAngle(const FourBarLengths& lengths, double crankAngle);

/// Extremes over all assemblable crank angles, or nullopt if the linkage never assembles.
std::optional<TransmissionRange> fourBarTransmissionRange(const FourBarLengths& lengths);

/// The worst min(μ, π − μ) (rad) over the crank angles from `from` to `to` (rad, from the frame
/// line, either order): exact, from μ at the two ends and at every θ = kπ between them; nullopt
/// if one of those angles cannot be assembled. Whether every angle between assembles is the
/// caller's to know (a range the linkage was seen to move through, or assembly_range.h).
std::optional<double> worstTransmissionBetween(const FourBarLengths& lengths, double from, double to);

}  // namespace linkwright::kinematics
