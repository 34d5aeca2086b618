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

#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"
#include "kinematics/tune/tolerance_dimensions.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

/// The most samples one study runs.
inline constexpr std::size_t kMaxToleranceSamples = 100'000;
/// The largest first sample index (2^53: exact as a double, so as a Python or JSON number).
inline constexpr std::uint64_t kMaxToleranceFirstSample = std::uint64_t{1} << 53;
/// The most values a band held whole may have (grid inputs × output columns): 2·10⁶, so its
/// nominal, lowest and highest values take 48 MB.
inline constexpr std::size_t kMaxToleranceBandValues = 2'000'000;
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
  /// Whether the study keeps the band at every grid input (ToleranceBand's nominal, low and
  /// high, and the nominal sweep: at most kMaxToleranceBandValues inputs × columns); false:
  /// only each column's worst deviation, the grid read in windows, in memory that does not
  /// grow with the grid.
  bool band = true;
  bool operator==(const MonteCarloSpec&) const = default;
};

/// Error naming "tolerance", "samples", "firstSample" or "perDimension[i]", the value and the
/// accepted range (or "band": the band would exceed kMaxToleranceBandValues for `inputs` grid inputs), unless the spec fits `mechanism`: a finite tolerance ≥ 0 below its shortest
/// length dimension (so every length stays positive), 1 ≤ samples ≤ kMaxToleranceSamples,
/// firstSample ≤ kMaxToleranceFirstSample, each perDimension naming one of its dimensions once
/// with a finite ± ≥ 0, below the length itself for a length.
std::optional<Error> checkMonteCarloSpec(const MonteCarloSpec& spec, const Mechanism& mechanism,
                                         std::size_t inputs = 1);

/// The most grid inputs a band of `mechanism` kept whole may have: kMaxToleranceBandValues
/// over its output columns.
std::size_t maxToleranceBandInputs(const Mechanism& mechanism);

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
  /// Per grid sample, the column's unit (NaN where undefined); empty unless MonteCarloSpec::band.
  std::vector<double> nominal;
  std::vector<double> low;   ///< lowest value of any sample (NaN where none had one)
  std::vector<double> high;  ///< highest value
  /// max |value − nominal| over the grid's range and the samples (NaN: none): the samples'
  /// worst linkage found on the grid, then refined between the grid inputs either side, on
  /// both linkages' poses solved there (so it is that linkage's worst, not its grid's).
  double worstDeviation = 0.0;
  std::size_t worstGridSample = 0;     ///< the grid input nearest to it (index into the grid)
  double worstInput = 0.0;             ///< where, in the input column's unit (deg, length, s)
  double sampledWorstDeviation = 0.0;  ///< the same linkage's worst at the grid's inputs alone
  std::uint64_t worstLinkage = 0;      ///< the Monte-Carlo sample that deviates most (its index)
};

/// The confidence the Monte-Carlo error's bounds are stated at.
inline constexpr double kToleranceConfidence = 0.95;

/// The band's sampling error for n samples in it, from order statistics alone (whatever the
/// outputs' distribution, if continuous): at one input the band [low, high] is the range of n
/// draws, whose coverage of the population is Beta(n − 1, 2), so one more linkage falls outside
/// it with chance 2/(n + 1); a column's worst deviation is the largest of the n samples' own
/// worst deviations over the grid, so one more linkage deviates more with chance 1/(n + 1).
struct MonteCarloError {
  std::size_t samples = 0;  ///< n, the samples in the band
  /// 2/(n + 1): the chance that one more linkage is outside the band at a given input (the
  /// expected fraction of all linkages outside it); 1 for n < 2.
  double outsideBand = 1.0;
  /// With kToleranceConfidence, at most this fraction of all linkages lies outside the band
  /// at a given input: 1 − y for the y where n·yⁿ⁻¹ − (n − 1)·yⁿ = 1 − confidence.
  double outsideBandBound = 1.0;
  /// 1/(n + 1): the chance that one more linkage's worst deviation over the grid exceeds a
  /// column's reported worst; 1 for n = 0.
  double beyondWorst = 1.0;
  /// With kToleranceConfidence, at most this fraction of all linkages deviates more than the
  /// reported worst: 1 − (1 − confidence)^(1/n).
  double beyondWorstBound = 1.0;
};

/// The error of a band of `samples` samples, its bounds at `confidence` (in (0, 1)).
MonteCarloError monteCarloError(std::size_t samples, double confidence = kToleranceConfidence);

/// The samples in the band needed so that with `confidence` at most `fraction` (in (0, 1)) of
/// all linkages lies outside it at a given input: the least n whose outsideBandBound ≤ fraction.
std::size_t toleranceSamplesFor(double fraction, double confidence = kToleranceConfidence);

struct MonteCarloResult {
  MonteCarloSpec spec;
  std::vector<ToleranceDimension> dimensions;
  SweepResult nominal;     ///< the nominal sweep, whole; empty unless MonteCarloSpec::band
  std::size_t inputs = 0;  ///< the grid's size
  std::vector<ToleranceBand> bands;
  std::size_t used = 0;          ///< samples in the bands
  std::size_t notAssembled = 0;  ///< samples that could not be assembled at some grid input
  std::size_t singular = 0;      ///< samples that met a toggle (rates undefined) on the grid
  MonteCarloError error;         ///< the band's sampling error, for the `used` samples
};

/// The study of `mechanism` over `spec`'s grid; without the band (MonteCarloSpec::band false)
/// the grid is read `window` inputs at a time. Progress in Monte-Carlo samples. Fails for an invalid
/// mechanism, grid or Monte-Carlo spec (the message names the field), a nominal linkage that
/// does not assemble (and move) at every input of the grid, or with ErrorCode::Cancelled.
Result<MonteCarloResult> toleranceMonteCarlo(const Mechanism& mechanism, const SweepSpec& spec,
                                             const MonteCarloSpec& monteCarlo, const RunControl& control = {},
                                             std::size_t window = kToleranceWindow);

/// The value of the grid's input column (sweepColumns' first: an angle in degrees, a length
/// or a time) at grid sample `sample`, without the sweep.
double toleranceInputAt(const SweepColumn& input, const SweepSpec& spec, std::size_t sample);

}  // namespace linkwright::kinematics
