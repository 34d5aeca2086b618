#pragma once
// The crank angles at which a four-bar can be assembled, found exactly. With a = crank,
// d = frame, the diagonal BD from the crank tip to the rocker pivot has
//   BD² = a² + d² − 2ad·cos θ,
// and the coupler (b) and rocker (c) close the loop iff |b − c| ≤ BD ≤ b + c. So
//   (a² + d² − (b+c)²) / 2ad  ≤  cos θ  ≤  (a² + d² − (b−c)²) / 2ad,
// which gives zero, one or two closed intervals of θ (or the full turn).

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/sweep.h"

#include <vector>

namespace linkwright::kinematics {

struct InputRange {
  bool fullRotation = false;       ///< the crank can turn through 360°
  std::vector<AngleRange> ranges;  ///< rad, from ≤ to; empty and !fullRotation: never assembles
  /// The input's period: a crank's 2π (a range holds its angles in any turn); 0 for a linear
  /// input (a path position, an actuator length), whose ranges hold only the values in them.
  double period = 2.0 * kPi;
  bool operator==(const InputRange&) const = default;

  /// True if `angle` (rad, any turn; a linear input's value) lies in the range, within `tolerance`.
  bool contains(double angle, double tolerance = 1e-12) const;
  /// `angle` itself if it lies in the range (or the range is empty), else the nearest range
  /// edge (rad, as stored in `ranges`): where a dragged or animated crank must stop.
  double clamp(double angle) const;
};

/// Assemblable crank angles for valid lengths. A range around θ = 0 is given as [−φ, φ], one
/// around θ = 180° as [φ, 360° − φ]; with two ranges the one in [0, 180°] comes first.
InputRange fourBarInputRange(const FourBarLengths& lengths);

}  // namespace linkwright::kinematics
