#pragma once
// The exact sensitivities of a linkage's outputs to its dimensions over a sweep: at every
// sample of the grid, ∂y/∂p for each output column y (each moving link's angle other than the
// input's, its ω and α, each moving point's x and y: sweep_columns.h's names and units) and
// each dimension p (tolerance_dimensions.h, per length unit). They come from the pose
// differentiated in jet arithmetic (analysis/pose_jet.h: the chain rule through the solver's
// closed forms, nothing differenced), at the sweep's own poses and branches. From them, the
// first-order worst case of a column under ± t on every dimension is max over the grid of
// Σ_p |∂y/∂p|·t: what the Monte Carlo's worst deviation (tolerance_monte_carlo.h) tends to
// as t shrinks, and bounds it to first order.

#include "kinematics/model/request_field.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/sweep.h"
#include "kinematics/solve/sweep_columns.h"
#include "kinematics/tune/tolerance_dimensions.h"

#include <functional>
#include <vector>

namespace linkwright::kinematics {

/// The output columns a tolerance study reports for `mechanism`, in sweepColumns' order:
/// link angles (not the input's), ω and α, then points' x and y.
std::vector<SweepColumn> toleranceColumns(const Mechanism& mechanism);

/// The input column's value (deg, length or s) at the sweep's `parameter` (sweepParameter's: an
/// angle or a time), between the grid's inputs as well.
double toleranceInputAtParameter(const SweepColumn& input, const SweepSpec& spec, double parameter);

/// A largest value of f, a function of the sweep's parameter, refined between the grid inputs
/// either side of grid input `sample` (over a full turn the turn's ends are neighbours) by golden
/// section. f returns a value below every one it has (−1 for a deviation) where it is undefined,
/// so the search turns away from there.
struct RefinedPeak {
  double parameter = 0.0;  ///< where: inside the grid's range (past a full turn's end, a turn back)
  double value = 0.0;      ///< f there; `atSample` (f at the grid input) if nothing larger is found
};
RefinedPeak refinePeakNear(const SweepSpec& spec, std::size_t sample, double atSample,
                           const std::function<double(double)>& f);

/// The value of an output column from a sweep's sample, with a link's angle unwrapped to
/// the turn nearest `near` (degrees) so that two sweeps' angles compare.
double toleranceColumnValue(const SweepColumn& column, const SweepResult& sweep, std::size_t sample, double near);

struct SweepSensitivities {
  std::vector<ToleranceDimension> dimensions;
  std::vector<SweepColumn> columns;
  SweepResult sweep;  ///< the nominal sweep: inputs, reports, values
  /// derivative[c][d][j]: ∂(column c)/∂(dimension d) at sample j, in the column's unit per
  /// length unit (deg/unit for angles); NaN where it is undefined: a rate at a toggle
  /// (the report Singular), anything where the linkage is not assembled.
  std::vector<std::vector<std::vector<double>>> derivative;

  /// max over the samples of |∂(column)/∂(dimension)|; NaN if it is defined nowhere.
  double largest(std::size_t column, std::size_t dimension) const;
  /// Σ_d |∂(column)/∂d|·tolerances[d] at `sample` (NaN where undefined); one ± per dimension.
  double firstOrderDeviation(std::size_t column, std::size_t sample, const std::vector<double>& tolerances) const;
  /// max over the samples of firstOrderDeviation, and where.
  double firstOrderWorst(std::size_t column, const std::vector<double>& tolerances,
                         std::size_t* sample = nullptr) const;
};

/// The samples of the grid a tolerance study holds at once when it works in windows.
inline constexpr std::size_t kToleranceWindow = kSweepWindow;

/// The sensitivities of `mechanism` over `spec`. Fails as sweep() does for an invalid
/// mechanism or spec.
Result<SweepSensitivities> sweepSensitivities(const Mechanism& mechanism, const SweepSpec& spec);

/// What a study reports of the sensitivities over the whole grid, folded window by window
/// (memory of `window` samples whatever the grid's size): SweepSensitivities's largest and
/// firstOrderWorst, the same numbers, and both refined between the grid's inputs.
struct SensitivitySummary {
  std::vector<ToleranceDimension> dimensions;
  std::vector<SweepColumn> columns;
  std::size_t inputs = 0;  ///< the grid's size
  /// [column][dimension]: the largest |∂y/∂p| over the grid's range, the grid's (below) refined
  /// between the grid inputs either side, as firstOrderWorst is.
  std::vector<std::vector<double>> largest;
  std::vector<std::vector<double>> sampledLargest;  ///< [column][dimension]: as SweepSensitivities::largest
  std::vector<std::vector<std::size_t>> largestAt;  ///< [column][dimension]: the grid input it is refined from
  /// [column]: the first-order worst case over the grid's range: the grid's (below) refined
  /// between the grid inputs either side, on the nominal pose solved and differentiated there.
  std::vector<double> firstOrderWorst;
  std::vector<double> firstOrderWorstInput;    ///< [column]: where, in the input column's unit
  std::vector<double> sampledFirstOrderWorst;  ///< [column]: as SweepSensitivities::firstOrderWorst
  std::vector<std::size_t> firstOrderWorstAt;  ///< [column]: the grid input it is refined from, 0 if nowhere
};

/// The summary of `mechanism`'s sensitivities over `spec` under `tolerances` (one per
/// dimension, length unit), `window` grid samples at a time; progress in grid samples, then a
/// few hundred poses per column and dimension refined. Fails as
/// sweepSensitivities does, or with ErrorCode::Cancelled.
Result<SensitivitySummary> sensitivitySummary(const Mechanism& mechanism, const SweepSpec& spec,
                                              const std::vector<double>& tolerances, const RunControl& control = {},
                                              std::size_t window = kToleranceWindow);

}  // namespace linkwright::kinematics
