#pragma once
// Editing any linkage by dragging one of its points (the general counterpart of
// design_edit.h's four-bar drags): the dragged point lands on the target by changing only the
// numbers that define it, and the points defined from it follow.
//
//   ground pivot      its position
//   crank tip         crank length, and the phase so the tip sits on the target now
//   RRR joint         both lengths (to its parents) and the branch (the target's side)
//   RRP slider        the rod length; the slider stays on its guide (target projected on it)
//   RPR slotted tip   the slotted link's length (target projected on the slot's line)
//   PRP pin           cannot be dragged: the guides fix it
//   attached point    its along/across offsets on the link
//   free point        its guess, and the length of every constraint that reaches it

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

namespace linkwright::kinematics {

/// Moves `point` of `mechanism` (solved as `pose` at input angle `inputAngle`, rad) to
/// `target` (length unit). Returns the edited mechanism, structurally checked; an Error names
/// the reason if a length would vanish or the point cannot be dragged. Assembly at other input
/// angles is not checked here: solve or sweep the result for that.
Result<Mechanism> dragPoint(const Mechanism& mechanism, const Pose& pose, double inputAngle, PointId point,
                            const Eigen::Vector2d& target);

}  // namespace linkwright::kinematics
