#pragma once
// Editing any linkage by dragging one of its points: the dragged point lands on the target by
// changing only the numbers that define it, and the points defined from it follow.
//
//   ground pivot      its position
//   crank tip         crank length, and the phase so the tip sits on the target now
//   point on a path   the input: the point slides along its path to the place nearest the target
//   actuator's end    its link's length, the branch, and the input (the actuator's length)
//   RRR joint         both lengths (to its parents) and the branch (the target's side)
//   RRP slider        the rod length; the slider stays on its guide (target projected on it)
//   RPR slotted tip   the slotted link's length (target projected on the slot's line)
//   PRP pin           cannot be dragged: the guides fix it
//   attached point    its along/across offsets on the link
//   free point        its guess, and the length of every constraint that reaches it
//
// Under DragRule::FrameLine a recognised four-bar keeps the frame its analyses are measured
// from: O2 and O4 slide along the frame line (a pivot may not pass the other), and dragging
// the crank tip B sets the crank length and turns the input, leaving the crank's phase.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

namespace linkwright::kinematics {

/// How a drag treats the frame of a four-bar.
enum class DragRule {
  Free,       ///< every point goes where it is dragged
  FrameLine,  ///< a recognised four-bar keeps its frame line (see above); others drag freely
};

/// A mechanism after a drag, and the input angle (rad) to show it at.
struct PointDrag {
  Mechanism mechanism;
  double inputAngle = 0.0;
  bool operator==(const PointDrag&) const = default;
};

/// Moves `point` of `mechanism` (solved as `pose` at input angle `inputAngle`, rad) to
/// `target` (length unit). Returns the edited mechanism, structurally checked, and the input
/// angle (unchanged but for the crank tip under FrameLine); an Error names the reason if a
/// length would vanish or the point cannot be dragged. Assembly at other input angles is not
/// checked here: solve or sweep the result for that.
Result<PointDrag> dragPoint(const Mechanism& mechanism, const Pose& pose, double inputAngle, PointId point,
                            const Eigen::Vector2d& target, DragRule rule = DragRule::Free);

/// Moves vertex `vertex` of the polyline path that drives `point` to `target` (length unit);
/// the driver's coordinate is left as it is. An Error names the vertex if the point has no
/// such vertex or the path would get a segment of no length.
Result<Mechanism> dragPathVertex(const Mechanism& mechanism, PointId point, std::size_t vertex,
                                 const Eigen::Vector2d& target);

}  // namespace linkwright::kinematics
