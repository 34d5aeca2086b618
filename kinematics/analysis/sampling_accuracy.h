#pragma once
// How wrong are the peaks a user reads off a table? A motion study or spreadsheet samples the
// cycle N times per revolution and reports the largest |ω|, |α|, speed and acceleration and the
// extreme angles among its samples; a frame-based tool also gets ω and α by differencing
// positions between frames. This measures both against the exact peaks (refined between
// samples on the exact solver, extrema.h), for the speed–accuracy trade the user picks.
// The crank turns at constant ω (α = 0), as in those tools, and must turn fully.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

enum class DerivativeMethod {
  Exact,             ///< ω, α, v, a from the solver at each sample (Linkwright)
  FiniteDifference,  ///< central differences of sampled positions (a frame-based tool)
};

/// The exact peaks of one linkage: per moving link (not the driven crank) its largest |ω| and
/// |α| and, unless it turns fully, its extreme angles; per moving point its largest speed and
/// acceleration magnitude. Units: rad, rad/s, rad/s², length unit/s, length unit/s².
struct PeakSet {
  std::vector<double> linkOmega;
  std::vector<double> linkAlpha;
  std::vector<double> linkMinAngle;  ///< empty entry (NaN-free): see linkRocks
  std::vector<double> linkMaxAngle;
  std::vector<bool> linkRocks;  ///< false for a link that turns fully (no extreme angles)
  std::vector<double> pointSpeed;
  std::vector<double> pointAcceleration;
  bool operator==(const PeakSet&) const = default;
};

/// The worst error over a linkage's peaks when read off samples, relative for rates (|read −
/// exact| / exact) and absolute for angles (rad).
struct PeakError {
  double omega = 0.0;
  double alpha = 0.0;
  double speed = 0.0;
  double acceleration = 0.0;
  double angle = 0.0;
  /// The worst of the relative errors.
  double worstRate() const;
  bool operator==(const PeakError&) const = default;
};

/// The exact peaks at crank speed `omega` (rad/s), refined to 1e-12 rad of crank angle between
/// `samplesPerRevolution` samples. Errors: invalid mechanism or ω, or a crank that cannot turn
/// fully.
Result<PeakSet> exactPeaks(const Mechanism& mechanism, double omega, std::size_t samplesPerRevolution = 360);

/// The peaks read off `samplesPerRevolution` (≥ 3) evenly spaced samples from crank angle 0,
/// with rates from the solver or by central differences of the sampled positions; free points
/// are solved with `newton`.
Result<PeakSet> sampledPeaks(const Mechanism& mechanism, double omega, std::size_t samplesPerRevolution,
                             DerivativeMethod method, const NewtonSettings& newton = {});

/// The worst error of `read` against `exact` (same linkage).
PeakError peakError(const PeakSet& read, const PeakSet& exact);

}  // namespace linkwright::kinematics
