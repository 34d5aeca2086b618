#pragma once
// The instant centres at the document's pose and the coupler's frame there (the moving
// centrode is drawn in it), as the document derives them for the canvas; or why there are
// none (the core's sentence: no body model for this linkage).

#include "kinematics/analysis/centrodes.h"
#include "kinematics/analysis/instant_centres.h"

#include <QString>

#include <optional>

namespace linkwright::ui {

struct CentresAtPose {
  std::optional<kinematics::InstantCentres> centres;
  std::optional<kinematics::CouplerFrame> frame;
  QString reason;
};

}  // namespace linkwright::ui
