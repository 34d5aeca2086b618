#pragma once
// The centrodes of a four-bar's coupler (a slider-crank's rod): the path of its instant centre
// I13 relative to the frame over a sweep, traced in the frame (the fixed centrode) and in the
// coupler's own frame (the moving centrode). The moving centrode rolls on the fixed one without
// slipping, touching it at I13 (Norton §6.5; Uicker, Pennock & Shigley §3.20). Each centre is
// instant_centres.h's at the sample; where I13 is at infinity or indeterminate (the coupler
// translates for an instant, or every joint is in line), or farther than kCentrodeReach
// linkage sizes from the crank pivot, the curves break: they run off towards infinity there.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <Eigen/Core>

#include <vector>

namespace linkwright::kinematics {

/// How far (in linkage sizes, InstantCentres::scale) a centrode is followed from the crank
/// pivot before it breaks: beyond, the centre is nearly at infinity and a drawing of it would
/// dwarf the linkage.
inline constexpr double kCentrodeReach = 10.0;

/// A point fixed on the coupler, in the coupler's frame: origin at its first joint B, x along
/// B→C, y 90° CCW from x (length unit).
struct CouplerFrame {
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  ///< B in the frame of the mechanism
  double angle = 0.0;                           ///< direction of B→C, rad CCW from +x

  /// `local` (coupler frame) in the frame of the mechanism.
  Eigen::Vector2d toWorld(const Eigen::Vector2d& local) const;
  /// `world` (frame of the mechanism) in the coupler frame.
  Eigen::Vector2d toLocal(const Eigen::Vector2d& world) const;
};

/// Both centrodes as runs of consecutive samples where I13 is finite and within reach.
struct Centrodes {
  std::vector<std::vector<Eigen::Vector2d>> fixed;   ///< frame of the mechanism (length unit)
  std::vector<std::vector<Eigen::Vector2d>> moving;  ///< coupler frame (length unit), run for run
};

/// The coupler frame of `mechanism` (a four-bar or a slider-crank, as instantCentres takes)
/// at `pose`. InvalidStructure otherwise.
Result<CouplerFrame> couplerFrame(const Mechanism& mechanism, const Pose& pose);

/// The centrodes over the assembled samples of `sweep` (positions are enough). Errors as
/// instantCentres.
Result<Centrodes> centrodes(const Mechanism& mechanism, const SweepResult& sweep);

}  // namespace linkwright::kinematics
