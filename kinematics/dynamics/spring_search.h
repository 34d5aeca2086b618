#pragma once
// Spring balancing with the ends searched: the spring from a point on a chosen link to a point
// on the frame that makes the crank's RMS driving torque least over a turn. For one placement
// the best stiffness and free length are spring_balance.h's least squares, which needs only the
// spring's length L(θ) and its rate L'(θ); both follow from the link's pose and velocities per
// unit crank rate without solving the linkage again (a point at (u, v) in the link's frame
// moves with the link). So the placement (u, v, x, y) is searched directly:
//   1. a grid over u in [−½, 3⁄2] and v in [−½, ½] of the link's length, and (x, y) over the
//      box the linkage sweeps, widened by a quarter of its size each way (9 values an axis);
//   2. from the best of the grid, a compass search (each axis ± a step, the step halved when
//      none improves, down to 1e-6 of the linkage's size), kept within those bounds.
// Placements where the spring's length comes within 1e-3 of the linkage's size of zero are
// skipped (L' is not defined there), as are those needing k ≤ 0. Deterministic: no random
// starts. The answer is then built as a design change, two points added to the mechanism,
// and sized again by balanceBySpring, the one path every spring balance goes through.

#include "kinematics/dynamics/spring_balance.h"

#include <string>

namespace linkwright::kinematics {

/// A spring balance with its ends found, and the mechanism with those ends as points.
struct SpringPlacement {
  Mechanism mechanism;      ///< the mechanism with two points added: the end on the link and the frame's
  SpringBalance balance;    ///< the spring between them (balanceBySpring on `mechanism`)
  LinkFramePoint onLink;    ///< the link end in the link's frame, length unit
  Eigen::Vector2d onFrame;  ///< the frame end, length unit
  /// True when the best placement lies on the search's bounds (above): an end allowed further
  /// out might do better
  bool atBound = false;
};

/// The spring `name` from a point on `link` to a point on the frame that minimises the RMS
/// driving torque over `turn` (one crank turn at constant ω). The two points are named
/// `name`_link and `name`_frame (with a number added if taken). Errors: the turn's, "link" for
/// a link the mechanism does not have, "spring" when no placement lowers the RMS.
Result<SpringPlacement> searchSpringBalance(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                            const SweepSpec& turn, const std::string& link,
                                            const std::string& name = "spring");

}  // namespace linkwright::kinematics
