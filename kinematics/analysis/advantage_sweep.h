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

/// Where the output comes to rest between two samples (a rocker's limit, a slider's dead
/// centre, a ram's reversal): the velocity ratio is Finite at samples `sample` and
/// `sample` + 1 and passes through zero between them, at `fraction` ∈ [0, 1) of the way by
/// linear interpolation, as a plot reads it.
struct OutputRest {
  std::size_t sample = 0;
  double fraction = 0.0;
  bool operator==(const OutputRest&) const = default;
};

/// The rests of `series` in sample order. A sign change through a pole (the ratio running off
/// to ±∞ where the crank cannot drive) is not a rest: the ratio's size grows towards a pole
/// and shrinks after it, while towards a zero it shrinks and grows after it.
std::vector<OutputRest> outputRests(const AdvantageSeries& series);

/// Why `mechanism` has no velocity ratio, or nothing when it has one.
std::optional<Error> ratioUnavailable(const Mechanism& mechanism);

}  // namespace linkwright::kinematics
