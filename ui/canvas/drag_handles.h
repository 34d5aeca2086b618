#pragma once
// The handles the canvas offers for dragging: which points have one, in picking order
// (points on links, then moving joints, then ground pivots, so a pin over a pivot wins), with
// each one's undo merge key, its name in "Move C" and its status-bar hint. A four-bar keeps
// its named handles (O2, O4, B, C, P), whose drags the core's dragFourBar understands.

#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/design/design_edit.h"
#include "kinematics/design/mechanism_design.h"
#include "kinematics/model/ids.h"

#include <QString>

#include <optional>
#include <vector>

namespace linkwright::ui {

/// The mechanism point a four-bar handle sits on.
kinematics::PointId handlePoint(kinematics::FourBarHandle handle);
/// The four-bar handle on `point` of a four-bar's mechanism.
std::optional<kinematics::FourBarHandle> fourBarHandleOn(kinematics::PointId point);
/// What dragging it does, for the status bar.
QString handleHint(kinematics::FourBarHandle handle);

/// The points with a handle, in picking order.
std::vector<kinematics::PointId> draggablePoints(const DrawingPlan& plan);
/// The point's name as drawn ("O₂", "E").
QString dragPointName(const kinematics::Mechanism& mechanism, kinematics::PointId point);
/// What dragging `point` does, for the status bar.
QString dragHint(const kinematics::Design& design, const kinematics::Mechanism& mechanism, kinematics::PointId point);

}  // namespace linkwright::ui
