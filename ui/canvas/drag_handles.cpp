#include "ui/canvas/drag_handles.h"

#include "ui/document/edit_design_command.h"

#include "kinematics/model/fourbar.h"

#include <QCoreApplication>

namespace linkwright::ui {

using kinematics::FourBarHandle;
namespace fourbar = kinematics::fourbar;

kinematics::PointId handlePoint(FourBarHandle handle) {
  switch (handle) {
  case FourBarHandle::O2: return fourbar::kO2;
  case FourBarHandle::O4: return fourbar::kO4;
  case FourBarHandle::B: return fourbar::kB;
  case FourBarHandle::C: return fourbar::kC;
  case FourBarHandle::CouplerPoint: return fourbar::kCouplerPoint;
  }
  return fourbar::kO2;
}

int handleMergeKey(FourBarHandle handle) {
  switch (handle) {
  case FourBarHandle::O2: return merge::kDragO2;
  case FourBarHandle::O4: return merge::kDragO4;
  case FourBarHandle::B: return merge::kDragB;
  case FourBarHandle::C: return merge::kDragC;
  case FourBarHandle::CouplerPoint: return merge::kDragCouplerPoint;
  }
  return -1;
}

QString handleName(FourBarHandle handle) {
  switch (handle) {
  case FourBarHandle::O2: return QStringLiteral("O\u2082");
  case FourBarHandle::O4: return QStringLiteral("O\u2084");
  case FourBarHandle::B: return QStringLiteral("B");
  case FourBarHandle::C: return QStringLiteral("C");
  case FourBarHandle::CouplerPoint: return QStringLiteral("P");
  }
  return {};
}

QString handleHint(FourBarHandle handle) {
  const char* context = "LinkageView";
  switch (handle) {
  case FourBarHandle::O2:
    return QCoreApplication::translate(context, "Drag O\u2082 along the frame line to change the frame length");
  case FourBarHandle::O4:
    return QCoreApplication::translate(context, "Drag O\u2084 along the frame line to change the frame length");
  case FourBarHandle::B: return QCoreApplication::translate(context, "Drag B to change the crank length and angle");
  case FourBarHandle::C: return QCoreApplication::translate(context, "Drag C to change the coupler and rocker lengths");
  case FourBarHandle::CouplerPoint:
    return QCoreApplication::translate(context, "Drag P to move the coupler point on the coupler");
  }
  return {};
}

} // namespace linkwright::ui
