#include "ui/canvas/design_drag.h"

#include "ui/canvas/drag_handles.h"
#include "ui/document/mechanism_document.h"

#include "kinematics/design/design_edit.h"
#include "kinematics/design/point_drag.h"
#include "kinematics/solve/pose_solver.h"

namespace linkwright::ui {

namespace k = kinematics;

k::Result<DesignDrag> dragDesign(const MechanismDocument& document, k::PointId point, const Eigen::Vector2d& target) {
  const double angle = document.crankAngle();
  if (const k::FourBarDesign* fourBar = document.fourBar()) {
    const auto handle = fourBarHandleOn(point);
    if (!handle) return k::Error{k::ErrorCode::InvalidValue, "point", "this point cannot be dragged"};
    const auto outcome = k::dragFourBar(*fourBar, angle, *handle, target);
    if (!outcome) return outcome.error();
    return DesignDrag{outcome->design, outcome->crankAngle, outcome->originShift};
  }
  k::MechanismDesign design = *document.linkage();
  auto dragged = k::dragPoint(design.mechanism, document.pose(), angle, point, target);
  if (!dragged) return dragged.error();
  // Positions only: the question is whether it assembles here, not how fast it moves.
  const auto solved = k::solvePose(*dragged, {angle, design.omega, design.alpha}, {false, false});
  if (!solved) return solved.error();
  design.mechanism = std::move(*dragged);
  return DesignDrag{std::move(design), angle, 0.0};
}

}  // namespace linkwright::ui
