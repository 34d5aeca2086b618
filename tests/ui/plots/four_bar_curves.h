#pragma once
// The plot curves of the default four-bar (thesis crank-rocker, with the ids of fourbar.h),
// for tests that name a four-bar quantity without building a panel.

#include "ui/plots/plot_quantity.h"

#include "kinematics/design/design.h"
#include "kinematics/solve/pose_solver.h"

#include <vector>

namespace linkwright::ui::test {

inline const std::vector<PlotCurve>& fourBarCurves() {
  static const std::vector<PlotCurve> curves = [] {
    const kinematics::Mechanism m =
        kinematics::makeFourBar(kinematics::kThesisCrankRocker, kinematics::Branch::Open).value();
    return plotCurves(m, kinematics::solvePose(m, {}).value());
  }();
  return curves;
}

inline const PlotCurve& fourBarCurve(PlotQuantity quantity) { return *findCurve(fourBarCurves(), quantity); }

/// The four-bar's quantities, in checkbox order.
inline std::vector<PlotQuantity> fourBarQuantities() {
  std::vector<PlotQuantity> out;
  for (const PlotCurve& c : fourBarCurves()) out.push_back(c.quantity);
  return out;
}

}  // namespace linkwright::ui::test
