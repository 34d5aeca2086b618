#pragma once
// A drag on the canvas turned into a new design, by the core: a four-bar's named points go
// through dragFourBar (lengths, branch, crank angle, frame re-anchored at O2), any other
// linkage's points through dragPoint. The result must also assemble at the crank angle it is
// shown at, so the dragged point lands under the pointer; if not, the solver's sentence says
// why.

#include "kinematics/design/mechanism_design.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

namespace linkwright::ui {

class MechanismDocument;

struct DesignDrag {
  kinematics::Design design;
  double crankAngle = 0.0;   ///< rad, where the crank is shown after the drag
  double originShift = 0.0;  ///< four-bar O2 drags: how far the origin moved along x
};

/// The design after dragging `point` of `document`'s design to `target` (model units).
kinematics::Result<DesignDrag> dragDesign(const MechanismDocument& document, kinematics::PointId point,
                                          const Eigen::Vector2d& target);

}  // namespace linkwright::ui
