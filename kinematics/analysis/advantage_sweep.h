#pragma once
// The velocity ratio and the ideal mechanical advantage of a crank-driven linkage at every
// sample of a sweep (instant_centres.h gives their derivation, from Kennedy's theorem), as
// columns a plot draws against the crank angle. A sample that could not be assembled, or where
// a centre the ratio needs is indeterminate or unresolved, has RatioKind::Undefined; a toggle,
// where a ratio's denominator vanishes, RatioKind::Infinite. Values are zero wherever the kind
// is not Finite: never NaN or infinity.

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// One column per ratio, one entry per sample of the sweep.
struct AdvantageSeries {
  RatioBodies bodies;  ///< input a (the crank) and output b, by their numbers
  /// Turning output: ωb/ωa (dimensionless). Sliding output: v/ωa (length unit per rad).
  std::vector<Ratio> velocityRatio;
  /// Turning output: Tb/Ta = ωa/ωb (dimensionless). Sliding output: F/Ta = ωa/v (1 / length unit).
  std::vector<Ratio> advantage;
  bool operator==(const AdvantageSeries&) const = default;
};

/// The ratios at every sample of `sweep`, a sweep of `mechanism` with every point's position
/// (the default selection). Only positions are read, so samples at a toggle (Singular) get
/// their ratios too. Errors: a linkage without a crank input about a frame pin or without an
/// output jointed to the frame (InvalidStructure, naming which), those of centreModel, or a
/// sweep without every point's positions.
Result<AdvantageSeries> advantageSeries(const Mechanism& mechanism, const SweepResult& sweep);

/// Why `mechanism` has no velocity ratio, or nothing when it has one.
std::optional<Error> ratioUnavailable(const Mechanism& mechanism);

}  // namespace linkwright::kinematics
