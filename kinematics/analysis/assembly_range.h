#pragma once
// The crank angles at which a four-bar can be assembled, found exactly. With a = crank,
// d = frame, the diagonal BD from the crank tip to the rocker pivot has
//   BD² = a² + d² − 2ad·cos θ,
// and the coupler (b) and rocker (c) close the loop iff |b − c| ≤ BD ≤ b + c. So
//   (a² + d² − (b+c)²) / 2ad  ≤  cos θ  ≤  (a² + d² − (b−c)²) / 2ad,
// which gives zero, one or two closed intervals of θ (or the full turn).

#include "kinematics/model/fourbar.h"
#include "kinematics/solve/sweep.h"

#include <vector>

namespace linkwright::kinematics {

struct InputRange {
  bool fullRotation = false;       ///< the crank can turn through 360°
  std::vector<AngleRange> ranges;  ///< rad, from ≤ to; empty and !fullRotation: never assembles
  bool operator==(const InputRange&) const = default;

  /// True if `angle` (rad, any turn) lies in the range, within `tolerance` rad.
  bool contains(double angle, double tolerance = 1e-12) const;
  /// `angle` itself if it lies in the range (or the range is empty), else the nearest range
  /// edge (rad, as stored in `ranges`): where a dragged or animated crank must stop.
  double clamp(double angle) const;
};

/// Assemblable crank angles for valid lengths. A range around θ = 0 is given as [−φ, φ], one
/// around θ = 180° as [φ, 360° − φ]; with two ranges the one in [0, 180°] comes first.
InputRange fourBarInputRange(const FourBarLengths& lengths);

}  // namespace linkwright::kinematics
