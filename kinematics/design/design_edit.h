#pragma once
// Editing a four-bar by dragging its points: the geometry that turns a dragged position into
// new lengths, branch and crank angle. It lives in the core so that the GUI holds no
// kinematics of its own and the rule is tested here. The frame line stays the +x axis, so the
// ground pivots move along it.

#include "kinematics/design/design.h"

#include <Eigen/Core>

namespace linkwright::kinematics {

enum class FourBarHandle {
  O2,            ///< crank pivot: moves along the frame line, changing the frame length
  O4,            ///< rocker pivot: likewise
  B,             ///< crank tip: sets crank length and crank angle
  C,             ///< coupler–rocker joint: sets coupler and rocker lengths and the branch
  CouplerPoint,  ///< the point on the coupler: sets its along/across offsets
};

/// A design after a drag, and the crank angle (rad) it is shown at.
struct DragOutcome {
  FourBarDesign design;
  double crankAngle = 0.0;
  /// Shift of the origin along x (length unit) when O2 moved: the frame is re-anchored at
  /// O2, so a view that wants O4 to stay put scrolls by this much.
  double originShift = 0.0;
  bool operator==(const DragOutcome&) const = default;
};

/// Applies a drag of `handle` to `target` (model coordinates, O2 at the origin before the
/// drag) at crank angle `crankAngle`. Fails, naming the reason, if a length would not be
/// positive or the result cannot be assembled at its crank angle; then nothing should change.
Result<DragOutcome> dragFourBar(const FourBarDesign& design, double crankAngle, FourBarHandle handle,
                                const Eigen::Vector2d& target);

}  // namespace linkwright::kinematics
