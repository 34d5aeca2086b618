#pragma once
// The handles the canvas offers for dragging: which points have one, in picking order
// (points on links, then moving joints, then ground pivots, so a pin over a pivot wins), with
// its name in "Move C" and its status-bar hint (a recognised four-bar's points say what the
// frame-line rule of the core's dragPoint does with them).

#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/model/ids.h"
#include "kinematics/model/recognise.h"

#include <QString>

#include <optional>
#include <vector>

namespace linkwright::ui {

/// The points with a handle, in picking order.
std::vector<kinematics::PointId> draggablePoints(const DrawingPlan& plan);
/// The point's name as drawn ("O₂", "E").
QString dragPointName(const kinematics::Mechanism& mechanism, kinematics::PointId point);
/// What dragging `point` does, for the status bar.
QString dragHint(const std::optional<kinematics::FourBarStructure>& fourBar, const kinematics::Mechanism& mechanism,
                 kinematics::PointId point);

}  // namespace linkwright::ui
