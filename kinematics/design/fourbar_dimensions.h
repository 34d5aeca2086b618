#pragma once
// A recognised four-bar's named dimensions (model/recognise.h), read and set on its mechanism:
// the four lengths, the branch and the point P on the coupler. The dimensions editor shows a
// four-bar by these names, and the CLI's --branch and --coupler-point set them, on a four-bar
// however it was built or stored (its point order, the frame's direction, the crank's phase).

#include "kinematics/model/fourbar.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/result.h"

#include <optional>

namespace linkwright::kinematics {

/// The point a four-bar's editors call P: the first point fixed on the coupler, its offsets
/// measured along B→C and 90° CCW from it (whichever way the coupler link runs).
struct CouplerPoint {
  PointId id;
  CouplerPointSpec spec;
};
std::optional<CouplerPoint> couplerPointOf(const Mechanism& mechanism, const FourBarStructure& fourBar);

/// `mechanism` with the four-bar's lengths: O2, the frame's direction, the crank's phase, the
/// branch and the points on the coupler stay. Checking the lengths is the design's job.
Mechanism withFourBarLengths(const Mechanism& mechanism, const FourBarStructure& fourBar,
                             const FourBarLengths& lengths);

/// `mechanism` with the four-bar on `branch` (open: C left of B→O4).
Mechanism withFourBarBranch(const Mechanism& mechanism, const FourBarStructure& fourBar, Branch branch);

/// `mechanism` with P at `spec` (a point named "P" is added on the coupler if there is none),
/// or without P when `spec` is empty. Fails if the four-bar has no coupler link to carry P.
Result<Mechanism> withCouplerPoint(const Mechanism& mechanism, const FourBarStructure& fourBar,
                                   std::optional<CouplerPointSpec> spec);

}  // namespace linkwright::kinematics
