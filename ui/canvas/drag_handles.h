#pragma once
// The handles the canvas offers for dragging: which points have one, and the vertices of the
// paths driven points follow, in picking order (points on links, then moving joints, then path
// vertices, then ground pivots, so a pin over a pivot wins), with its name in "Move C" and its
// status-bar hint (a recognised four-bar's points say what the frame-line rule of the core's
// dragPoint does with them).

#include "ui/canvas/mechanism_drawing.h"

#include "kinematics/model/ids.h"
#include "kinematics/model/recognise.h"

#include <QString>

#include <optional>
#include <vector>

namespace linkwright::ui {

/// What a handle moves: a point, or vertex `pathVertex` of the path that drives `point`.
struct DragHandle {
  DragHandle() = default;
  /// A point's own handle (implicit: a point is dragged by its handle).
  DragHandle(kinematics::PointId p, std::optional<std::size_t> vertex = std::nullopt) : point(p), pathVertex(vertex) {}
  kinematics::PointId point;
  std::optional<std::size_t> pathVertex;
  bool operator==(const DragHandle&) const = default;
};

/// The handles of `mechanism` drawn as `plan`, in picking order.
std::vector<DragHandle> dragHandles(const DrawingPlan& plan, const kinematics::Mechanism& mechanism);
/// The point's name as drawn ("O₂", "E").
QString dragPointName(const kinematics::Mechanism& mechanism, kinematics::PointId point);
/// The handle's name for "Move …": the point's, or "tip path point 2".
QString dragHandleName(const kinematics::Mechanism& mechanism, const DragHandle& handle);
/// What dragging the handle does, for the status bar.
QString dragHint(const std::optional<kinematics::FourBarStructure>& fourBar, const kinematics::Mechanism& mechanism,
                 const DragHandle& handle);

}  // namespace linkwright::ui
