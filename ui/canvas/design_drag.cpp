#include "ui/canvas/design_drag.h"

#include "ui/document/mechanism_document.h"

#include "kinematics/design/point_drag.h"
#include "kinematics/solve/pose_solver.h"

namespace linkwright::ui {

namespace k = kinematics;

k::Result<DesignDrag> dragDesign(const MechanismDocument& document, const DragHandle& handle,
                                 const Eigen::Vector2d& target) {
  k::Design design = document.design();
  k::Result<k::PointDrag> dragged = k::PointDrag{};
  if (handle.pathVertex) {
    auto moved = k::dragPathVertex(design.mechanism, handle.point, *handle.pathVertex, target);
    if (!moved) return moved.error();
    dragged = k::PointDrag{std::move(*moved), document.crankAngle()};
  } else {
    dragged = k::dragPoint(design.mechanism, document.pose(), document.crankAngle(), handle.point, target,
                           k::DragRule::FrameLine);
  }
  if (!dragged) return dragged.error();
  // Positions only: the question is whether it assembles here, not how fast it moves.
  const auto solved =
      k::solvePose(dragged->mechanism, {dragged->inputAngle, design.omega, design.alpha}, {false, false});
  if (!solved) return solved.error();
  design.mechanism = std::move(dragged->mechanism);
  return DesignDrag{std::move(design), dragged->inputAngle};
}

}  // namespace linkwright::ui
