#pragma once
// Time ratio and stroke of a crank-driven slotted rocker (the crank-shaper), exactly. The
// rocker stops where its slot is tangent to the crank circle: with O4 at distance d from O2
// in direction ψ and crank r, the crank pin B satisfies B·(B − O4) = 0, i.e.
//   cos(θ − ψ) = r / d,   θ = ψ ± acos(r/d).
// The crank turns through 2·acos(r/d) on one stroke and 2π − 2·acos(r/d) on the other, so
// the time ratio (slow stroke / quick stroke) is (π + 2·asin(r/d)) / (π − 2·asin(r/d)). The
// ram's stroke is the distance between its positions at the two limits.

#include "kinematics/model/shaper.h"

#include <optional>

namespace linkwright::kinematics {

struct QuickReturnReport {
  double firstLimitCrankAngle = 0.0;   ///< rad in [0, 2π)
  double secondLimitCrankAngle = 0.0;  ///< rad in [0, 2π)
  double slowStrokeCrankArc = 0.0;     ///< rad
  double quickStrokeCrankArc = 0.0;    ///< rad
  double timeRatio = 1.0;              ///< slow / quick, ≥ 1
  double rockerSwing = 0.0;            ///< rad, angle between the rocker's limits
  double stroke = 0.0;                 ///< ram travel between the limits (length unit)
  bool operator==(const QuickReturnReport&) const = default;
};

/// The limits, time ratio and stroke of a crank-shaper; nullopt if the geometry is invalid,
/// if it is a Whitworth form (pivot inside the crank circle: the slotted link has no limits),
/// or if the ram cannot be assembled at a limit.
std::optional<QuickReturnReport> shaperQuickReturn(const ShaperGeometry& geometry, Branch branch = Branch::Open);

} // namespace linkwright::kinematics
