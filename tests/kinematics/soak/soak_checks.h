#pragma once
// What the soak asserts of every sweep (soak_main.cpp): no value that is not finite where the
// sweep says a value exists, loop closure, branch continuity between samples, and the exact
// rates against central differences in time. Plain functions returning findings, so that a
// run over 10^6 linkages can report them all and a unit test can feed them corrupted sweeps.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/sweep.h"

#include <string>
#include <vector>

namespace linkwright::test {

struct SweepCheck {
  std::vector<std::string> findings;  ///< empty when every check passed
  std::size_t assembled = 0;          ///< samples checked for finiteness, closure and continuity
  std::size_t ratesCompared = 0;      ///< samples whose rates were compared with differences
  std::size_t ratesSkipped = 0;       ///< near a toggle, or the stencil left the sweep's branch
  double worstClosure = 0.0;          ///< largest link or constraint misfit over the linkage's size
  double worstRateRatio = 0.0;        ///< largest |exact − difference| over its tolerance (≤ 1 passes)
};

/// Checks `sweep`, the result of sweep(mechanism, spec) with the default request; compares
/// rates with time differences at up to `rateSamples` samples spread over the sweep.
/// `inputScale`: how far the input moves for a radian's worth of motion (1 for a crank; for a
/// linear driver a length of the linkage, so the differences' step moves it as little).
SweepCheck checkSweep(const kinematics::Mechanism& mechanism, const kinematics::SweepSpec& spec,
                      const kinematics::SweepResult& sweep, std::size_t rateSamples, double inputScale = 1.0);

/// Closure tolerance: 1e-9 of the linkage's size, a thousand times the misfit the suite's
/// closed-form dyads reach at length ratios of 1e6 (1e-15 of the size times 1e6 over the
/// shortest link) and above Newton's default tolerance.
inline constexpr double kClosureTolerance = 1e-9;

}  // namespace linkwright::test
