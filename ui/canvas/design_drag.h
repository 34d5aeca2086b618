#pragma once
// A drag on the canvas turned into a new design, by the core's dragPoint: a recognised
// four-bar keeps its frame line (DragRule::FrameLine: O2 and O4 slide along it, B turns the
// crank), any other linkage's points go where they are dragged. The result must also assemble
// at the crank angle it is shown at, so the dragged point lands under the pointer; if not, the
// solver's sentence says why.

#include "ui/canvas/drag_handles.h"

#include "kinematics/design/design.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

namespace linkwright::ui {

class MechanismDocument;

struct DesignDrag {
  kinematics::Design design;
  double crankAngle = 0.0;  ///< rad, where the crank is shown after the drag
};

/// The design after dragging `handle` of `document`'s design to `target` (model units): a
/// point (point_drag.h's dragPoint) or a vertex of a driven point's path (dragPathVertex).
kinematics::Result<DesignDrag> dragDesign(const MechanismDocument& document, const DragHandle& handle,
                                          const Eigen::Vector2d& target);

}  // namespace linkwright::ui
