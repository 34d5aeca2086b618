#include "kinematics/tune/tolerance_monte_carlo.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/mechanism_check.h"
#include "kinematics/model/number_text.h"
#include "kinematics/solve/pose_solver.h"
#include "kinematics/tune/tolerance_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

// SplitMix64 (Steele, Lea and Flood 2014): one 64-bit state, a fixed sequence.
std::uint64_t splitMix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The shortest length dimension: a tolerance must stay below it.
std::optional<ToleranceDimension> shortestLength(const std::vector<ToleranceDimension>& dimensions) {
  std::optional<ToleranceDimension> out;
  for (const ToleranceDimension& d : dimensions)
    if (parameterUnit(d.parameter.slot) == ParameterUnit::Length && (!out || d.value < out->value)) out = d;
  return out;
}

bool allOk(const SweepResult& s) {
  return std::all_of(s.report.begin(), s.report.end(), [](const PoseReport& r) { return r.status == PoseStatus::Ok; });
}

}  // namespace

std::size_t maxToleranceBandInputs(const Mechanism& mechanism) {
  return kMaxToleranceBandValues / std::max<std::size_t>(toleranceColumns(mechanism).size(), 1);
}

std::optional<Error> checkMonteCarloSpec(const MonteCarloSpec& spec, const Mechanism& mechanism, std::size_t inputs) {
  const auto shortest = shortestLength(toleranceDimensions(mechanism));
  const double bound = shortest ? shortest->value : std::numeric_limits<double>::infinity();
  const std::string unit = " " + mechanism.lengthUnit;
  if (!(spec.tolerance >= 0.0 && spec.tolerance < bound))
    return Error{ErrorCode::InvalidValue, "tolerance",
                 "tolerance must be finite, at least 0 and less than the shortest length" +
                     (shortest ? " (" + shortest->name + ", " + formatShort(bound) + unit + ")" : std::string()) +
                     +" (got " + formatNumber(spec.tolerance) + (std::isfinite(spec.tolerance) ? unit : "") + ")"};
  if (spec.samples < 1 || spec.samples > kMaxToleranceSamples)
    return Error{ErrorCode::InvalidValue, "samples",
                 "samples must be between 1 and " + std::to_string(kMaxToleranceSamples) + " (got " +
                     std::to_string(spec.samples) + ")"};
  if (spec.firstSample > kMaxToleranceFirstSample)
    return Error{ErrorCode::InvalidValue, "firstSample",
                 "firstSample must be between 0 and " + std::to_string(kMaxToleranceFirstSample) + " (got " +
                     std::to_string(spec.firstSample) + ")"};
  if (spec.band && inputs > maxToleranceBandInputs(mechanism))
    return Error{ErrorCode::InvalidValue, "band",
                 "a band kept at every input holds " + std::to_string(toleranceColumns(mechanism).size()) +
                     " columns' nominal, lowest and highest values there: at most " +
                     std::to_string(maxToleranceBandInputs(mechanism)) + " inputs for this linkage (got " +
                     std::to_string(inputs) + ")"};
  const std::vector<ToleranceDimension> dimensions = toleranceDimensions(mechanism);
  std::string names;
  for (const ToleranceDimension& d : dimensions) names += (names.empty() ? "" : ", ") + d.name;
  for (std::size_t i = 0; i < spec.perDimension.size(); ++i) {
    const DimensionTolerance& t = spec.perDimension[i];
    const std::string field = "perDimension[" + std::to_string(i) + "]";
    const auto d = std::find_if(dimensions.begin(), dimensions.end(),
                                [&](const ToleranceDimension& x) { return x.name == t.dimension; });
    if (d == dimensions.end())
      return Error{ErrorCode::InvalidValue, field,
                   "no dimension is named '" + t.dimension + "' (this linkage's: " + names + ")"};
    for (std::size_t j = 0; j < i; ++j)
      if (spec.perDimension[j].dimension == t.dimension)
        return Error{ErrorCode::InvalidValue, field, t.dimension + " is given a tolerance twice"};
    const bool length = parameterUnit(d->parameter.slot) == ParameterUnit::Length;
    const double below = length ? d->value : std::numeric_limits<double>::infinity();
    if (!(t.tolerance >= 0.0 && t.tolerance < below))
      return Error{ErrorCode::InvalidValue, field,
                   "the tolerance of " + t.dimension + " must be finite, at least 0" +
                       (length ? " and less than the length (" + formatShort(below) + unit + ")" : std::string()) +
                       " (got " + formatNumber(t.tolerance) + (std::isfinite(t.tolerance) ? unit : "") + ")"};
  }
  return std::nullopt;
}

std::vector<double> dimensionTolerances(const MonteCarloSpec& spec, const std::vector<ToleranceDimension>& dimensions) {
  std::vector<double> out;
  for (const ToleranceDimension& d : dimensions) {
    double t = spec.tolerance;
    for (const DimensionTolerance& own : spec.perDimension)
      if (own.dimension == d.name) t = own.tolerance;
    out.push_back(t);
  }
  return out;
}

std::vector<double> toleranceSampleOffsets(const MonteCarloSpec& spec, const std::vector<double>& tolerances,
                                           std::size_t sample) {
  std::uint64_t state = spec.seed ^ (0xd1b54a32d192ed03ULL * (static_cast<std::uint64_t>(sample) + 1));
  std::vector<double> out;
  for (const double tolerance : tolerances) {
    // 53 random bits: u uniform in [0, 1), then [−t, t).
    const double u = static_cast<double>(splitMix(state) >> 11) * 0x1.0p-53;
    out.push_back((2.0 * u - 1.0) * tolerance);
  }
  return out;
}

namespace {

// The chance that the range of n draws covers less than y of the population, I_y(n − 1, 2).
double rangeCoverageBelow(std::size_t n, double y) {
  const double m = static_cast<double>(n);
  return m * std::pow(y, m - 1.0) - (m - 1.0) * std::pow(y, m);
}

// The fraction outside the range of n ≥ 2 draws not exceeded with `confidence`: 1 − y for the
// y where rangeCoverageBelow(n, y) = 1 − confidence (increasing in y), by bisection.
double outsideRangeBound(std::size_t n, double confidence) {
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (rangeCoverageBelow(n, mid) < 1.0 - confidence ? lo : hi) = mid;
  }
  return 1.0 - lo;
}

}  // namespace

MonteCarloError monteCarloError(std::size_t samples, double confidence) {
  MonteCarloError e;
  e.samples = samples;
  const double n = static_cast<double>(samples);
  if (samples >= 2) {
    e.outsideBand = 2.0 / (n + 1.0);
    e.outsideBandBound = outsideRangeBound(samples, confidence);
  }
  if (samples >= 1) {
    e.beyondWorst = 1.0 / (n + 1.0);
    e.beyondWorstBound = -std::expm1(std::log1p(-confidence) / n);
  }
  return e;
}

std::size_t toleranceSamplesFor(double fraction, double confidence) {
  if (!(fraction > 0.0 && fraction < 1.0 && confidence > 0.0 && confidence < 1.0)) return 0;
  // outsideRangeBound falls as n grows: the least n within `fraction`, by bisection on n.
  std::size_t lo = 2, hi = 4;
  while (outsideRangeBound(hi, confidence) > fraction) hi *= 2;
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    if (outsideRangeBound(mid, confidence) > fraction) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

double toleranceInputAt(const SweepColumn& input, const SweepSpec& spec, std::size_t sample) {
  return toleranceInputAtParameter(input, spec, sweepParameter(spec, sample));
}

namespace {

// A linkage's value in `column` at the sweep's `parameter`, an angle unwrapped to the turn
// nearest `near`; nullopt where its pose or rates do not exist there.
std::optional<double> columnValueAt(const Mechanism& m, const SweepSpec& spec, const SweepColumn& column,
                                    double parameter, double near, Pose& pose) {
  const DriverState driver = sweepDriverAt(spec, parameter);
  if (solvePoseInto(m, driver, {true, true}, pose).status != PoseStatus::Ok) return std::nullopt;
  return column.valueOf(pose, driver.position, near);
}

// Refines `band`'s worst deviation, that of the Monte-Carlo linkage `m` at grid input
// band.worstGridSample, between the grid inputs either side: a golden-section search of
// |value − nominal| on both linkages' poses solved between them, never below the sampled worst.
void refineWorst(const Mechanism& nominal, const Mechanism& m, const SweepSpec& spec, const SweepColumn& input,
                 ToleranceBand& band) {
  Pose nominalPose, samplePose;
  preparePose(nominal, nominalPose);
  preparePose(m, samplePose);
  const RefinedPeak peak =
      refinePeakNear(spec, band.worstGridSample, band.worstDeviation, [&](double parameter) -> double {
        const auto v0 = columnValueAt(nominal, spec, band.column, parameter, 0.0, nominalPose);
        const auto v = v0 ? columnValueAt(m, spec, band.column, parameter, *v0, samplePose) : std::nullopt;
        return v ? std::abs(*v - *v0) : -1.0;
      });
  band.worstDeviation = peak.value;
  band.worstInput = toleranceInputAtParameter(input, spec, peak.parameter);
}

// The nominal values of each output column over a window of the grid, and the window's
// samples of one Monte-Carlo linkage folded against them.
struct SampleFold {
  bool notAssembled = false;
  bool singular = false;
  std::vector<double> worst;                // per column, this sample's worst deviation so far
  std::vector<std::size_t> at;              // and where (grid index)
  std::vector<std::vector<double>> values;  // per column, per grid input: with the band only

  void reset(std::size_t columns, bool band, std::size_t inputs) {
    notAssembled = singular = false;
    worst.assign(columns, kUndefined);
    at.assign(columns, 0);
    values.resize(band ? columns : 0);
    for (auto& v : values) v.resize(inputs);
  }

  // Window `part` from grid input `first`, against the nominal values `nominal[c][j]` of the
  // same inputs (j from `offset` in them). False once the sample cannot be in the band.
  bool fold(const std::vector<ToleranceBand>& bands, const SweepResult& part, std::size_t first,
            const std::vector<std::vector<double>>& nominal, std::size_t offset) {
    if (!part.notAssembled.empty() || std::any_of(part.report.begin(), part.report.end(), [](const PoseReport& r) {
          return r.status == PoseStatus::NotAssemblable;
        })) {
      notAssembled = true;
      return false;
    }
    if (!allOk(part)) singular = true;  // read on: a later input may not assemble
    if (singular) return true;
    for (std::size_t c = 0; c < bands.size(); ++c) {
      for (std::size_t j = 0; j < part.size(); ++j) {
        const double near = nominal[c][offset + j];
        const double v = toleranceColumnValue(bands[c].column, part, j, near);
        if (!values.empty()) values[c][first + j] = v;
        const double deviation = std::abs(v - near);
        if (std::isnan(worst[c]) || deviation > worst[c]) {
          worst[c] = deviation;
          at[c] = first + j;
        }
      }
    }
    return true;
  }
};

// The output columns' values over a window of the nominal sweep, into nominal[c][offset + j].
void nominalValues(const std::vector<ToleranceBand>& bands, const SweepResult& part, std::size_t offset,
                   std::vector<std::vector<double>>& nominal) {
  nominal.resize(bands.size());
  for (std::size_t c = 0; c < bands.size(); ++c) {
    nominal[c].resize(std::max(nominal[c].size(), offset + part.size()));
    for (std::size_t j = 0; j < part.size(); ++j) nominal[c][offset + j] = bands[c].column.value(part, j);
  }
}

// Below this many values (inputs × columns) a study without the band keeps the nominal values
// (8 MB) rather than sweep the nominal again beside each sample.
constexpr std::size_t kNominalCacheValues = std::size_t{1} << 20;

}  // namespace

Result<MonteCarloResult> toleranceMonteCarlo(const Mechanism& mechanism, const SweepSpec& spec,
                                             const MonteCarloSpec& monteCarlo, const RunControl& control,
                                             std::size_t window) {
  if (auto e = checkMechanism(mechanism)) return *e;
  if (auto e = checkSweepSpec(spec, inputKind(mechanism))) return *e;
  if (auto e = checkMonteCarloSpec(monteCarlo, mechanism, spec.samples)) return *e;
  MonteCarloResult out;
  out.spec = monteCarlo;
  out.dimensions = toleranceDimensions(mechanism);
  out.inputs = spec.samples;
  const std::size_t n = spec.samples;
  for (const SweepColumn& c : toleranceColumns(mechanism)) {
    const std::size_t kept = monteCarlo.band ? n : 0;
    out.bands.push_back({c, std::vector<double>(kept), std::vector<double>(kept, kUndefined),
                         std::vector<double>(kept, kUndefined), kUndefined, 0});
  }
  // With the band the grid is one window (the nominal sweep and each sample's kept whole), as
  // it is below `window` inputs; else the nominal's values are kept when they are few, or
  // swept again beside each sample's windows.
  window = monteCarlo.band ? n : std::max<std::size_t>(window, 1);
  const bool whole = n <= window;
  const bool cached = whole || n * out.bands.size() <= kNominalCacheValues;
  std::vector<std::vector<double>> nominal;
  const auto nominalFailed = [](const std::optional<std::string>& failure) {
    return Error{ErrorCode::NotAssemblable, "linkage",
                 "the nominal linkage must assemble and move at every input of the grid for a tolerance study: " +
                     failure.value_or("it meets a toggle on the grid, where its rates are undefined")};
  };
  if (whole) {
    auto swept = sweep(mechanism, spec);
    if (!swept) return swept.error();
    if (!allOk(*swept)) return nominalFailed(swept->firstFailure);
    nominalValues(out.bands, *swept, 0, nominal);
    if (monteCarlo.band) {
      for (std::size_t c = 0; c < out.bands.size(); ++c) out.bands[c].nominal = nominal[c];
      out.nominal = std::move(*swept);
    }
  } else {
    auto started = SweepWindows::start(mechanism, spec, SolveRequest{}, window);
    if (!started) return started.error();
    SweepWindows windows = std::move(started).value();
    bool ok = true;
    while (const SweepResult* part = windows.next(control.cancel)) {
      ok = ok && allOk(*part);
      if (cached) nominalValues(out.bands, *part, windows.first(), nominal);
    }
    if (control.cancelled()) return cancelledError();
    if (!ok) return nominalFailed(windows.summary().firstFailure);
  }
  const std::vector<double> tolerances = dimensionTolerances(monteCarlo, out.dimensions);
  SweepResult sample;
  SampleFold fold;
  std::vector<std::vector<double>> nominalWindow;
  for (std::size_t k = 0; k < monteCarlo.samples; ++k) {
    if (control.cancelled()) return cancelledError();
    const std::size_t index = static_cast<std::size_t>(monteCarlo.firstSample) + k;
    const Mechanism m =
        offsetDimensions(mechanism, out.dimensions, toleranceSampleOffsets(monteCarlo, tolerances, index));
    fold.reset(out.bands.size(), monteCarlo.band, n);
    if (whole) {
      if (auto e = sweepInto(m, spec, SolveRequest{}, sample)) return *e;
      fold.fold(out.bands, sample, 0, nominal, 0);
    } else {
      auto started = SweepWindows::start(m, spec, SolveRequest{}, window);
      if (!started) return started.error();
      SweepWindows windows = std::move(started).value();
      std::optional<SweepWindows> nominalWindows;
      if (!cached)
        nominalWindows.emplace(std::move(SweepWindows::start(mechanism, spec, SolveRequest{}, window)).value());
      while (const SweepResult* part = windows.next(control.cancel)) {
        const std::size_t first = windows.first();
        if (nominalWindows) nominalValues(out.bands, *nominalWindows->next(), 0, nominalWindow);
        if (!fold.fold(out.bands, *part, first, cached ? nominal : nominalWindow, cached ? first : 0)) break;
      }
      if (control.cancelled()) return cancelledError();
    }
    if (control.progress) control.progress(k + 1, monteCarlo.samples);
    if (fold.notAssembled) {
      ++out.notAssembled;
      continue;
    }
    if (fold.singular) {
      ++out.singular;
      continue;
    }
    ++out.used;
    // The sample's worst against the samples' before it: the earliest wins a tie, as it would
    // folded sample by sample and input by input.
    for (std::size_t c = 0; c < out.bands.size(); ++c) {
      ToleranceBand& band = out.bands[c];
      if (std::isnan(band.worstDeviation) || fold.worst[c] > band.worstDeviation) {
        band.worstDeviation = fold.worst[c];
        band.worstGridSample = fold.at[c];
        band.worstLinkage = index;
      }
      if (!monteCarlo.band) continue;
      for (std::size_t j = 0; j < n; ++j) {
        const double v = fold.values[c][j];
        if (std::isnan(band.low[j]) || v < band.low[j]) band.low[j] = v;
        if (std::isnan(band.high[j]) || v > band.high[j]) band.high[j] = v;
      }
    }
  }
  // Each column's worst linkage refined between the grid's inputs: a few hundred poses.
  const SweepColumn input = sweepColumns(mechanism, SolveRequest{}, spec.time.has_value()).front();
  for (ToleranceBand& band : out.bands) {
    band.sampledWorstDeviation = band.worstDeviation;
    if (std::isnan(band.worstDeviation)) continue;
    if (control.cancelled()) return cancelledError();
    const Mechanism m =
        offsetDimensions(mechanism, out.dimensions, toleranceSampleOffsets(monteCarlo, tolerances, band.worstLinkage));
    refineWorst(mechanism, m, spec, input, band);
  }
  out.error = monteCarloError(out.used);
  return out;
}

}  // namespace linkwright::kinematics
