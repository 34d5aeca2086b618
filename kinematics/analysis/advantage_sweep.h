#pragma once
// The velocity ratio and the ideal mechanical advantage of a four-bar or slider-crank at every
// sample of a sweep (instant_centres.h gives their derivation, from Kennedy's theorem), as
// columns a plot draws against the crank angle. A sample that could not be assembled has
// RatioKind::Undefined; a toggle, where a ratio's denominator vanishes, RatioKind::Infinite.
// Values are zero wherever the kind is not Finite: never NaN or infinity.

#include "kinematics/analysis/instant_centres.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"

#include <vector>

namespace linkwright::kinematics {

/// One column per ratio, one entry per sample of the sweep.
struct AdvantageSeries {
  CentreLinkage linkage = CentreLinkage::FourBar;
  /// Four-bar: ω4/ω2 (dimensionless). Slider-crank: v/ω2 (length unit per rad).
  std::vector<Ratio> velocityRatio;
  /// Four-bar: T4/T2 = ω2/ω4 (dimensionless). Slider-crank: F/T2 = ω2/v (1 / length unit).
  std::vector<Ratio> advantage;
  bool operator==(const AdvantageSeries&) const = default;
};

/// The ratios at every sample of `sweep`, a sweep of `mechanism` with every point's position
/// (the default selection). Only positions are read, so samples at a toggle (Singular) get
/// their ratios too. Errors: a mechanism that is neither a four-bar nor a slider-crank
/// (InvalidStructure, as instantCentres), or a sweep without every point's positions.
Result<AdvantageSeries> advantageSeries(const Mechanism& mechanism, const SweepResult& sweep);

}  // namespace linkwright::kinematics
