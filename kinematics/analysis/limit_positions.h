#pragma once
// The rocker's limit (dead-centre) positions of a four-bar and the time ratio. The rocker
// stops (ω4 = 0) exactly when the crank and the coupler are collinear (thesis seed 000, eq.
// (14): ω4 ∝ sin(θ3 − θ2)), i.e. when C is at b + a (extended) or |b − a| (folded) from O2.
// With O4C = c and O2O4 = d, each is a triangle solved in closed form; of its two mirror
// images we keep those the linkage reaches on its assembly branch. For a crank turning at
// constant speed the two strokes take times in proportion to the crank arcs between the limit
// positions; their quotient (≥ 1) is the time ratio.

#include "kinematics/model/fourbar.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

struct LimitPosition {
  bool extended = false;     ///< crank and coupler in line (true) or folded over (false)
  double crankAngle = 0.0;   ///< rad in [0, 2π)
  double rockerAngle = 0.0;  ///< rad in (−π, π]
  bool operator==(const LimitPosition&) const = default;
};

struct LimitReport {
  std::vector<LimitPosition> positions;  ///< ordered by crank angle
  /// Only for a fully rotating crank with exactly two limits:
  std::optional<double> rockerSwing;          ///< rad, angle between the two rocker limits
  std::optional<double> timeRatio;            ///< slower stroke / quicker stroke, ≥ 1
  std::optional<double> slowStrokeCrankArc;   ///< rad
  std::optional<double> quickStrokeCrankArc;  ///< rad
  bool operator==(const LimitReport&) const = default;
};

/// Limit positions for valid lengths on the given branch.
LimitReport fourBarLimitPositions(const FourBarLengths& lengths, Branch branch);

}  // namespace linkwright::kinematics
