#pragma once
// The handles the canvas offers for dragging, in picking order (moving joints before ground
// pivots, so a pin over a pivot wins), with the point each one sits on, its undo merge key,
// its name in "Move C" and its status-bar hint.

#include "kinematics/model/design_edit.h"
#include "kinematics/model/ids.h"

#include <QString>

#include <array>

namespace linkwright::ui {

inline constexpr std::array<kinematics::FourBarHandle, 5> kDragHandles{
    kinematics::FourBarHandle::CouplerPoint, kinematics::FourBarHandle::C, kinematics::FourBarHandle::B,
    kinematics::FourBarHandle::O4, kinematics::FourBarHandle::O2};

/// The mechanism point the handle sits on.
kinematics::PointId handlePoint(kinematics::FourBarHandle handle);
/// The merge key (edit_design_command.h) of this handle's drags.
int handleMergeKey(kinematics::FourBarHandle handle);
/// The point's symbol: "O₂", "O₄", "B", "C", "P".
QString handleName(kinematics::FourBarHandle handle);
/// What dragging it does, for the status bar.
QString handleHint(kinematics::FourBarHandle handle);

} // namespace linkwright::ui
