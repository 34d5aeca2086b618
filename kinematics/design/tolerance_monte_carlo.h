#pragma once
// A Monte-Carlo tolerance study: N linkages, each with every dimension (tolerance_dimensions.h)
// moved independently by a uniform offset in [−t, +t] (the engineering default for a
// worst-case study: every part anywhere within its ± tolerance), each swept over the nominal
// grid with the real solver, and per output column (tolerance_sensitivity.h's) the band the
// curves fill (the lowest and highest value at each grid sample) and the worst deviation from
// the nominal curve over the grid and the samples. A sample that does not assemble at every
// input of the grid, or meets a toggle there (rates undefined), is counted, not hidden, and left
// out of the band. Sample k's offsets are a pure function of the seed and k (SplitMix64, a
// generator the standard does not vary between libraries), so a seed gives the same study on
// every machine, and a test can rebuild any sample alone (toleranceSampleOffsets).

#include "kinematics/design/tolerance_dimensions.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// The most samples one study runs.
inline constexpr std::size_t kMaxToleranceSamples = 100'000;
/// The largest first sample index (2^53: exact as a double, so as a Python or JSON number).
inline constexpr std::uint64_t kMaxToleranceFirstSample = std::uint64_t{1} << 53;
/// The seed when none is given.
inline constexpr std::uint64_t kDefaultToleranceSeed = 46;

/// A ± of one dimension's own, the dimension named as ToleranceDimension::name ("coupler
/// length", "O2 x", "O4 across the frame line").
struct DimensionTolerance {
  std::string dimension;
  double tolerance = 0.0;  ///< length unit, ≥ 0; a length's below that length
  bool operator==(const DimensionTolerance&) const = default;
};

struct MonteCarloSpec {
  double tolerance =
      0.0;  ///< ± on every dimension not named in perDimension, length unit, ≥ 0, below the shortest length
  std::size_t samples = 1000;  ///< 1 … kMaxToleranceSamples
  std::uint64_t seed = kDefaultToleranceSeed;
  /// The first sample's index, 0 … kMaxToleranceFirstSample: a study run in shards (samples
  /// [first, first + samples) each) has the samples of one run, and its bands are the shards'
  /// lowest and highest values.
  std::uint64_t firstSample = 0;
  /// The dimensions whose parts are made to a ± of their own (each named once).
  std::vector<DimensionTolerance> perDimension;
  bool operator==(const MonteCarloSpec&) const = default;
};

/// Error naming "tolerance", "samples", "firstSample" or "perDimension[i]", the value and the
/// accepted range, unless the spec fits `mechanism`: a finite tolerance ≥ 0 below its shortest
/// length dimension (so every length stays positive), 1 ≤ samples ≤ kMaxToleranceSamples,
/// firstSample ≤ kMaxToleranceFirstSample, each perDimension naming one of its dimensions once
/// with a finite ± ≥ 0, below the length itself for a length.
std::optional<Error> checkMonteCarloSpec(const MonteCarloSpec& spec, const Mechanism& mechanism);

/// The ± of each of `dimensions` (length unit): its own where spec.perDimension names it, else
/// spec.tolerance.
std::vector<double> dimensionTolerances(const MonteCarloSpec& spec, const std::vector<ToleranceDimension>& dimensions);

/// Sample k's offset of each dimension (length unit), uniform in ±tolerances[i]: the same
/// uniform draws whatever the tolerances, scaled by each.
std::vector<double> toleranceSampleOffsets(const MonteCarloSpec& spec, const std::vector<double>& tolerances,
                                           std::size_t sample);

/// One output column's band over the samples that assembled everywhere.
struct ToleranceBand {
  SweepColumn column;
  std::vector<double> nominal;      ///< per grid sample, the column's unit (NaN where undefined)
  std::vector<double> low;          ///< lowest value of any sample (NaN where none had one)
  std::vector<double> high;         ///< highest value
  double worstDeviation = 0.0;      ///< max |value − nominal| over grid and samples (NaN: none)
  std::size_t worstGridSample = 0;  ///< where (index into the grid)
};

struct MonteCarloResult {
  MonteCarloSpec spec;
  std::vector<ToleranceDimension> dimensions;
  SweepResult nominal;
  std::vector<ToleranceBand> bands;
  std::size_t used = 0;          ///< samples in the bands
  std::size_t notAssembled = 0;  ///< samples that could not be assembled at some grid input
  std::size_t singular = 0;      ///< samples that met a toggle (rates undefined) on the grid
};

/// The study of `mechanism` over `spec`'s grid. Fails for an invalid mechanism, grid or
/// Monte-Carlo spec (the message names the field), or a nominal linkage that does not
/// assemble (and move) at every input of the grid.
Result<MonteCarloResult> toleranceMonteCarlo(const Mechanism& mechanism, const SweepSpec& spec,
                                             const MonteCarloSpec& monteCarlo);

}  // namespace linkwright::kinematics
