#include "kinematics/design/tolerance_monte_carlo.h"

#include "kinematics/design/tolerance_sensitivity.h"
#include "kinematics/model/number_text.h"

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

std::optional<Error> checkMonteCarloSpec(const MonteCarloSpec& spec, const Mechanism& mechanism) {
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

Result<MonteCarloResult> toleranceMonteCarlo(const Mechanism& mechanism, const SweepSpec& spec,
                                             const MonteCarloSpec& monteCarlo) {
  auto nominal = sweep(mechanism, spec);
  if (!nominal) return nominal.error();
  if (auto e = checkMonteCarloSpec(monteCarlo, mechanism)) return *e;
  if (!allOk(*nominal))
    return Error{ErrorCode::NotAssemblable, "linkage",
                 "the nominal linkage must assemble and move at every input of the grid for a tolerance study: " +
                     nominal->firstFailure.value_or("it meets a toggle on the grid, where its rates are undefined")};
  MonteCarloResult out;
  out.spec = monteCarlo;
  out.dimensions = toleranceDimensions(mechanism);
  out.nominal = std::move(*nominal);
  const std::size_t n = out.nominal.size();
  for (const SweepColumn& c : toleranceColumns(mechanism)) {
    ToleranceBand band{
        c, std::vector<double>(n), std::vector<double>(n, kUndefined), std::vector<double>(n, kUndefined), kUndefined,
        0};
    for (std::size_t j = 0; j < n; ++j) band.nominal[j] = c.value(out.nominal, j);
    out.bands.push_back(std::move(band));
  }
  const std::vector<double> tolerances = dimensionTolerances(monteCarlo, out.dimensions);
  SweepResult sample;
  for (std::size_t k = 0; k < monteCarlo.samples; ++k) {
    const std::size_t index = static_cast<std::size_t>(monteCarlo.firstSample) + k;
    const Mechanism m =
        offsetDimensions(mechanism, out.dimensions, toleranceSampleOffsets(monteCarlo, tolerances, index));
    if (auto e = sweepInto(m, spec, SolveRequest{}, sample)) return *e;
    if (!sample.notAssembled.empty()) {
      ++out.notAssembled;
      continue;
    }
    if (!allOk(sample)) {
      ++out.singular;
      continue;
    }
    ++out.used;
    for (ToleranceBand& band : out.bands) {
      for (std::size_t j = 0; j < n; ++j) {
        const double v = toleranceColumnValue(band.column, sample, j, band.nominal[j]);
        if (std::isnan(band.low[j]) || v < band.low[j]) band.low[j] = v;
        if (std::isnan(band.high[j]) || v > band.high[j]) band.high[j] = v;
        const double deviation = std::abs(v - band.nominal[j]);
        if (std::isnan(band.worstDeviation) || deviation > band.worstDeviation) {
          band.worstDeviation = deviation;
          band.worstGridSample = j;
        }
      }
    }
  }
  return out;
}

}  // namespace linkwright::kinematics
