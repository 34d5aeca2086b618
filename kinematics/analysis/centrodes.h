#pragma once
// The centrodes of a linkage's first floating body (centre_model.h: a four-bar's coupler, a
// slider-crank's rod, a shaper's link), body k: the path of its instant centre I1k relative to
// the frame over a sweep, traced in the frame (the fixed centrode) and in the body's own frame
// (the moving centrode). The moving centrode rolls on the fixed one without slipping, touching
// it at I1k (Norton §6.5; Uicker, Pennock & Shigley §3.20). Each centre is instant_centres.h's
// at the sample; where I1k is at infinity, indeterminate or unresolved (the body translates for
// an instant, every joint is in line, or Kennedy's theorem does not reach it), or farther than
// kCentrodeReach linkage sizes from the anchor (the crank pivot), the curves break: they run off
// towards infinity there.

#include "kinematics/analysis/centre_model.h"
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

/// The frame of the body whose centrodes are traced: origin at its first link's first point
/// (a four-bar coupler's B), x towards that link's second point (C), y 90° CCW from x (length
/// unit).
struct CouplerFrame {
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  ///< the origin in the frame of the mechanism
  double angle = 0.0;                           ///< direction of its x axis, rad CCW from +x

  /// `local` (coupler frame) in the frame of the mechanism.
  Eigen::Vector2d toWorld(const Eigen::Vector2d& local) const;
  /// `world` (frame of the mechanism) in the coupler frame.
  Eigen::Vector2d toLocal(const Eigen::Vector2d& world) const;
};

/// Both centrodes as runs of consecutive samples where I1k is finite and within reach.
struct Centrodes {
  std::size_t body = 0;                             ///< k, the body's number (instant_centres.h); 0 when there are none
  std::vector<std::vector<Eigen::Vector2d>> fixed;  ///< frame of the mechanism (length unit)
  std::vector<std::vector<Eigen::Vector2d>> moving;  ///< coupler frame (length unit), run for run
};

/// The frame of `mechanism`'s first floating body at `pose`. InvalidStructure if every body is
/// jointed to the frame, or as centreModel.
Result<CouplerFrame> couplerFrame(const Mechanism& mechanism, const Pose& pose);

/// The frame of `model`'s centrode body (centrodeBody ≠ 0) at a pose of its mechanism.
CouplerFrame couplerFrame(const CentreModel& model, const Pose& pose);

/// The centrodes over the assembled samples of `sweep` (positions are enough). Errors as
/// instantCentres.
Result<Centrodes> centrodes(const Mechanism& mechanism, const SweepResult& sweep);

}  // namespace linkwright::kinematics
