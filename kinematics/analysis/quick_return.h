#pragma once
// Time ratio and stroke of a crank-driven slotted rocker (the crank-shaper), exactly. The
// rocker stops where its slot is tangent to the crank circle: with O4 at distance d from O2
// in direction ψ and crank r, the crank pin B satisfies B·(B − O4) = 0, i.e.
//   cos(θ − ψ) = r / d,   θ = ψ ± acos(r/d).
// The crank turns through 2·acos(r/d) on one stroke and 2π − 2·acos(r/d) on the other, so
// the time ratio (slow stroke / quick stroke) is (π + 2·asin(r/d)) / (π − 2·asin(r/d)). The
// ram's stroke is the distance between its positions at the two limits.
//
// Whitworth form (O4 inside the crank circle): the slotted link turns fully, so the ram's
// limits come from the last dyad instead: the ram stops where the link D→R lies along the
// slotted link, R = O4 + (a ± l)·e(φ) on the guide, i.e. sin φ = (h − y_O4)/(a ± l). Each
// such φ maps to the one crank angle whose pin lies on the slot's ray (quick_return.cpp).

#include "kinematics/model/shaper.h"

#include <optional>

namespace linkwright::kinematics {

struct QuickReturnReport {
  double firstLimitCrankAngle = 0.0;   ///< rad in [0, 2π)
  double secondLimitCrankAngle = 0.0;  ///< rad in [0, 2π)
  double slowStrokeCrankArc = 0.0;     ///< rad
  double quickStrokeCrankArc = 0.0;    ///< rad
  double timeRatio = 1.0;              ///< slow / quick, ≥ 1
  double rockerSwing = 0.0;            ///< rad, angle between the rocker's limits (2π: Whitworth)
  bool whitworth = false;              ///< the slotted link turns fully; the limits are the ram's
  double stroke = 0.0;                 ///< ram travel between the limits (length unit)
  bool operator==(const QuickReturnReport&) const = default;
};

/// The limits, time ratio and stroke of a crank-shaper or a Whitworth mechanism; nullopt if
/// the geometry is invalid, the ram has no two limits, or it cannot be assembled at one.
std::optional<QuickReturnReport> shaperQuickReturn(const ShaperGeometry& geometry, Branch branch = Branch::Open);

}  // namespace linkwright::kinematics
