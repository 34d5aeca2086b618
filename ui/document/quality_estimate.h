#pragma once
// The error a sampling quality buys on one linkage: the peaks a user reads off the displayed
// samples (largest |ω| and |α| of each link, speed and acceleration of each point) against the
// exact peaks refined between samples (kinematics/analysis/sampling_accuracy.h, the measurement
// docs/accuracy.md tabulates). Measured per design and sample count, never guessed; a crank that
// does not turn fully has no cycle to measure over, and the estimate then says so instead.

#include "kinematics/analysis/sampling_accuracy.h"
#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <QString>

#include <cstddef>
#include <optional>

namespace linkwright::ui {

struct QualityEstimate {
  std::size_t samplesPerRevolution = 0;  ///< the N the peaks were read off
  /// Worst errors (relative for rates, rad for angles); empty when they cannot be measured.
  std::optional<kinematics::PeakError> error;
  /// Why error is empty: a sentence for the user (the core's reason in `detail`).
  QString unavailable;
  QString detail;
  /// Wall time the measurement took, ms (exact and sampled peaks together).
  double measureMilliseconds = 0.0;
};

/// Measures peakError(sampledPeaks(N, exact rates, `newton`), exactPeaks) for `mechanism` with
/// its crank at |`omega`| rad/s (1 rad/s if zero: relative peak errors do not depend on it) and
/// α = 0. N = `samplesPerRevolution` (≥ 3).
QualityEstimate estimatePeakError(const kinematics::Mechanism& mechanism, double omega,
                                  std::size_t samplesPerRevolution, const kinematics::NewtonSettings& newton);

/// The crank speed the estimate uses for a design turning at `omega` rad/s.
double estimateOmega(double omega);

}  // namespace linkwright::ui
