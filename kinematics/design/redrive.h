#pragma once
// Driving a linkage from another joint: a four-bar from its rocker instead of its crank, a
// slider-crank from its piston (a compressor's linkage worked from the piston side) or back
// from its crank, a two-link arm from its shoulder instead of its tip. The swap is exact and
// local: the driver and a dyad joint next to it trade roles, so the linkage keeps every link,
// length and name, and the pose it is in:
//   - a crank B about A and an RRR joint C on B and a ground pivot D: C turns about D and
//     B becomes the RRR joint of A and C;
//   - a crank B about A and a slider C on B along a ground guide: C is driven along the guide
//     (a path segment over its stroke) and B becomes the RRR joint of A and C;
//   - a point C driven along a straight path and an RRR joint B of C and a ground pivot A: B
//     turns about A and C becomes a slider on the path's line.
// Whatever else the linkage has (a coupler point, a second loop) follows unchanged. The
// drive becomes constant speed on a grid over the new input's natural range; a motion law in
// the old input's coordinate means nothing for the new one.

#include "kinematics/design/design.h"
#include "kinematics/model/ids.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <string>
#include <vector>

namespace linkwright::kinematics {

/// A point the linkage can be driven from, and how the user sees it.
struct DriverChoice {
  PointId point;
  /// "crank about O2 (angle)", "rocker about O4 (angle)", "C along its guide (position)".
  std::string description;
  bool operator==(const DriverChoice&) const = default;
};

/// The driver the mechanism has first, then each point it can be driven from instead (see
/// above). Only the driver when there is no other, or when the driver is an actuator, an arc
/// or a polyline of several segments; empty without a driver.
std::vector<DriverChoice> driverChoices(const Mechanism& mechanism);

struct Redriven {
  Design design;
  /// The new driver's coordinate in the pose `design` had (rad for a crank, in [0, 2π); else
  /// the length unit): where the designer puts the new input so that nothing moves.
  double input = 0.0;
};

/// `design` driven from `point` (one of driverChoices), in the pose it has at input `input`
/// (rad or length unit): dyad branches are chosen so that this pose is the new linkage's at
/// the returned input. The grid: a crank over a full turn every 0.5° at the old driver's ω
/// (a linear driver's speed over the new crank's length), a point along a guide over its
/// stroke less 1 % at each end (a slider-crank cannot be driven from its piston through a
/// dead centre) at the old crank pin's speed |ω|·r; α and any time base are cleared.
/// Fails, naming "driver", if `point` is not a choice or the pose cannot be assembled.
Result<Redriven> driveFrom(const Design& design, PointId point, double input);

}  // namespace linkwright::kinematics
