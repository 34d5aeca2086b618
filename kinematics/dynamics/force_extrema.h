#pragma once
// The refined extremes of a force quantity over a sweep, with the core's extremes discipline
// (analysis/extrema.h): the best samples of the force sweep bracket each extreme, and a
// golden-section search refines it on poses solved between them, their forces solved afresh by
// inverse dynamics. So a peak shaking force does not depend on the sampling step: the Forces
// tab's peaks line and the lab report's forces caption both print these.

#include "kinematics/analysis/extrema.h"
#include "kinematics/dynamics/force_sweep.h"
#include "kinematics/dynamics/inverse_dynamics.h"

#include <functional>
#include <optional>

namespace linkwright::kinematics {

/// A quantity of one pose's forces (N, N·m, …).
using PoseForceQuantity = std::function<double(const PoseForces& forces)>;

/// The refined extremes of `quantity` over `forces`, the force sweep of `sweep` (a sweep of
/// `mechanism` over `spec` with `dynamics`); nullopt when no sample's forces are solved.
std::optional<Extrema> forceExtrema(const Mechanism& mechanism, const LinkageDynamics& dynamics, const SweepSpec& spec,
                                    const ForceSweep& forces, const PoseForceQuantity& quantity);

/// The peak shaking force |F_s| (N) and the shaking moment largest in size (N·m, signed), each
/// with where it occurs, refined as above.
struct ShakingPeaks {
  Extremum force;
  Extremum moment;
};
std::optional<ShakingPeaks> shakingPeaks(const Mechanism& mechanism, const LinkageDynamics& dynamics,
                                         const SweepSpec& spec, const ForceSweep& forces);

}  // namespace linkwright::kinematics
