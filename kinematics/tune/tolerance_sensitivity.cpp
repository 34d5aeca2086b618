#include "kinematics/tune/tolerance_sensitivity.h"

#include "kinematics/analysis/pose_jet.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/golden_section.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

bool isOutput(const SweepColumn& c) {
  switch (c.quantity) {
  case ColumnQuantity::LinkAngle:
  case ColumnQuantity::LinkOmega:
  case ColumnQuantity::LinkAlpha:
  case ColumnQuantity::PointX:
  case ColumnQuantity::PointY: return true;
  default: return false;
  }
}

// ∂(column)/∂p from the differentiated pose, in the column's unit per length unit.
double derivativeOf(const SweepColumn& c, const PoseJet& jet) {
  switch (c.quantity) {
  case ColumnQuantity::LinkAngle: return radToDeg(jet.linkAngle[c.index].valueSensitivity());
  case ColumnQuantity::LinkOmega: return jet.linkAngle[c.index].rateSensitivity();
  case ColumnQuantity::LinkAlpha: return jet.linkAngle[c.index].accelerationSensitivity();
  case ColumnQuantity::PointX: return jet.position[c.index].x.valueSensitivity();
  case ColumnQuantity::PointY: return jet.position[c.index].y.valueSensitivity();
  default: return kUndefined;
  }
}

}  // namespace

std::vector<SweepColumn> toleranceColumns(const Mechanism& m) {
  std::vector<SweepColumn> out;
  for (const SweepColumn& c : sweepColumns(m, SolveRequest{}))
    if (isOutput(c)) out.push_back(c);
  return out;
}

double toleranceInputAtParameter(const SweepColumn& input, const SweepSpec& spec, double parameter) {
  if (input.quantity == ColumnQuantity::Time) return parameter;
  return input.valueOf(Pose{}, sweepDriverAt(spec, parameter).position, 0.0);
}

RefinedPeak refinePeakNear(const SweepSpec& spec, std::size_t sample, double atSample,
                           const std::function<double(double)>& f) {
  RefinedPeak best{sweepParameter(spec, sample), atSample};
  const std::size_t n = spec.samples;
  if (n < 2) return best;
  const double step = sweepParameter(spec, 1) - sweepParameter(spec, 0);
  const bool fullTurn = !spec.time && std::abs(std::abs(spec.toAngle - spec.fromAngle) - 2.0 * kPi) < 1e-9;
  const double lo = sample > 0 ? sweepParameter(spec, sample - 1) : best.parameter - (fullTurn ? step : 0.0);
  const double hi = sample + 1 < n ? sweepParameter(spec, sample + 1) : best.parameter + (fullTurn ? step : 0.0);
  (void)goldenSection(
      [&](double parameter) {
        const double v = f(parameter);
        if (v > best.value) best = {parameter, v};
        return v;
      },
      std::min(lo, hi), std::max(lo, hi), GoldenGoal::Maximum, 1e-10);
  // A place found past an end of a full turn is the same pose a turn back inside it.
  if (fullTurn) {
    const double low = std::min(spec.fromAngle, spec.toAngle), high = std::max(spec.fromAngle, spec.toAngle);
    if (best.parameter < low) best.parameter += 2.0 * kPi;
    else if (best.parameter > high) best.parameter -= 2.0 * kPi;
  }
  return best;
}

double toleranceColumnValue(const SweepColumn& column, const SweepResult& sweep, std::size_t sample, double near) {
  const double v = column.value(sweep, sample);
  if (column.quantity != ColumnQuantity::LinkAngle) return v;
  return v - 360.0 * std::round((v - near) / 360.0);
}

double SweepSensitivities::largest(std::size_t column, std::size_t dimension) const {
  double worst = kUndefined;
  for (const double d : derivative[column][dimension])
    if (std::isfinite(d) && !(std::abs(d) <= worst)) worst = std::abs(d);
  return worst;
}

double SweepSensitivities::firstOrderDeviation(std::size_t column, std::size_t sample,
                                               const std::vector<double>& tolerances) const {
  double sum = 0.0;
  for (std::size_t d = 0; d < derivative[column].size(); ++d)
    sum += std::abs(derivative[column][d][sample]) * tolerances[d];
  return sum;
}

double SweepSensitivities::firstOrderWorst(std::size_t column, const std::vector<double>& tolerances,
                                           std::size_t* sample) const {
  double worst = kUndefined;
  for (std::size_t j = 0; j < sweep.size(); ++j) {
    const double d = firstOrderDeviation(column, j, tolerances);
    if (std::isfinite(d) && !(d <= worst)) {
      worst = d;
      if (sample != nullptr) *sample = j;
    }
  }
  return worst;
}

namespace {

// derivative[c][d][j] for the samples of `s`, a window of the nominal sweep from grid sample
// `first`; `stepped[d]` is steppedMechanism of dimension d. NaN where undefined.
void fillDerivatives(const Mechanism& mechanism, const std::vector<Mechanism>& stepped, const SweepSpec& spec,
                     const std::vector<SweepColumn>& columns, const SweepResult& s, std::size_t first,
                     std::vector<std::vector<std::vector<double>>>& derivative) {
  const std::size_t n = s.size();
  derivative.resize(columns.size());
  for (auto& column : derivative) {
    column.resize(stepped.size());
    for (auto& values : column) values.assign(n, kUndefined);
  }
  std::vector<Eigen::Vector2d> positions(mechanism.points.size());
  PoseJet jet;
  for (std::size_t d = 0; d < stepped.size(); ++d) {
    for (std::size_t j = 0; j < n; ++j) {
      if (!s.assembled(j)) continue;
      for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = s.position[i][j];
      if (!differentiatePose(mechanism, stepped[d], sweepDriver(spec, first + j), positions, jet)) continue;
      for (std::size_t c = 0; c < columns.size(); ++c)
        if (s.ok(j) || !columns[c].isRate()) derivative[c][d][j] = derivativeOf(columns[c], jet);
    }
  }
}

std::vector<Mechanism> steppedMechanisms(const Mechanism& mechanism,
                                         const std::vector<ToleranceDimension>& dimensions) {
  std::vector<Mechanism> out;
  for (const ToleranceDimension& d : dimensions) out.push_back(steppedMechanism(mechanism, d));
  return out;
}

}  // namespace

Result<SweepSensitivities> sweepSensitivities(const Mechanism& mechanism, const SweepSpec& spec) {
  auto nominal = sweep(mechanism, spec);
  if (!nominal) return nominal.error();
  SweepSensitivities out;
  out.dimensions = toleranceDimensions(mechanism);
  out.columns = toleranceColumns(mechanism);
  out.sweep = std::move(*nominal);
  fillDerivatives(mechanism, steppedMechanisms(mechanism, out.dimensions), spec, out.columns, out.sweep, 0,
                  out.derivative);
  return out;
}

Result<SensitivitySummary> sensitivitySummary(const Mechanism& mechanism, const SweepSpec& spec,
                                              const std::vector<double>& tolerances, const RunControl& control,
                                              std::size_t window) {
  auto started = SweepWindows::start(mechanism, spec, SolveRequest{}, window);
  if (!started) return started.error();
  SweepWindows windows = std::move(started).value();
  SensitivitySummary out;
  out.dimensions = toleranceDimensions(mechanism);
  out.columns = toleranceColumns(mechanism);
  out.largest.assign(out.columns.size(), std::vector<double>(out.dimensions.size(), kUndefined));
  out.firstOrderWorst.assign(out.columns.size(), kUndefined);
  out.firstOrderWorstAt.assign(out.columns.size(), 0);
  const std::vector<Mechanism> stepped = steppedMechanisms(mechanism, out.dimensions);
  // The window's derivatives folded as SweepSensitivities's largest and firstOrderWorst fold
  // the whole grid's: in the grid's order, so the same sample wins a tie.
  out.largestAt.assign(out.columns.size(), std::vector<std::size_t>(out.dimensions.size(), 0));
  SweepSensitivities part;
  while (const SweepResult* s = windows.next(control.cancel)) {
    const std::size_t first = windows.first();
    fillDerivatives(mechanism, stepped, spec, out.columns, *s, first, part.derivative);
    for (std::size_t c = 0; c < out.columns.size(); ++c) {
      for (std::size_t d = 0; d < out.dimensions.size(); ++d)
        for (std::size_t j = 0; j < s->size(); ++j)
          if (const double v = part.derivative[c][d][j]; std::isfinite(v) && !(std::abs(v) <= out.largest[c][d])) {
            out.largest[c][d] = std::abs(v);
            out.largestAt[c][d] = first + j;
          }
      for (std::size_t j = 0; j < s->size(); ++j) {
        double sum = 0.0;
        for (std::size_t d = 0; d < out.dimensions.size(); ++d)
          sum += std::abs(part.derivative[c][d][j]) * tolerances[d];
        if (std::isfinite(sum) && !(sum <= out.firstOrderWorst[c])) {
          out.firstOrderWorst[c] = sum;
          out.firstOrderWorstAt[c] = first + j;
        }
      }
    }
    out.inputs = first + s->size();
    if (control.progress) control.progress(out.inputs, spec.samples);
  }
  if (control.cancelled()) return cancelledError();
  // Each figure refined between the grid inputs either side of its grid input, on the nominal
  // pose solved and differentiated there: about forty poses a figure.
  out.sampledLargest = out.largest;
  out.sampledFirstOrderWorst = out.firstOrderWorst;
  const SweepColumn input = sweepColumns(mechanism, SolveRequest{}, spec.time.has_value()).front();
  out.firstOrderWorstInput.assign(out.columns.size(), kUndefined);
  Pose pose;
  preparePose(mechanism, pose);
  PoseJet jet;
  // Σ over the dimensions [from, to) of |∂(column c)/∂d|·weight(d) at the sweep's `parameter`;
  // −1 where the pose, or a rate column's rates, do not exist there.
  const auto weightedAt = [&](double parameter, std::size_t c, std::size_t from, std::size_t to, const auto& weight) {
    const DriverState driver = sweepDriverAt(spec, parameter);
    const PoseStatus status = solvePoseInto(mechanism, driver, {true, true}, pose).status;
    if (status == PoseStatus::NotAssemblable || (status != PoseStatus::Ok && out.columns[c].isRate())) return -1.0;
    double sum = 0.0;
    for (std::size_t d = from; d < to; ++d) {
      if (!differentiatePose(mechanism, stepped[d], driver, pose.position, jet)) return -1.0;
      sum += std::abs(derivativeOf(out.columns[c], jet)) * weight(d);
    }
    return std::isfinite(sum) ? sum : -1.0;
  };
  for (std::size_t c = 0; c < out.columns.size(); ++c) {
    for (std::size_t d = 0; d < out.dimensions.size(); ++d) {
      if (control.cancelled()) return cancelledError();
      if (std::isnan(out.largest[c][d])) continue;
      out.largest[c][d] = refinePeakNear(spec, out.largestAt[c][d], out.largest[c][d], [&](double parameter) {
                            return weightedAt(parameter, c, d, d + 1, [](std::size_t) { return 1.0; });
                          }).value;
    }
    const std::size_t j = out.firstOrderWorstAt[c];
    out.firstOrderWorstInput[c] = toleranceInputAtParameter(input, spec, sweepParameter(spec, j));
    if (std::isnan(out.firstOrderWorst[c])) continue;
    const RefinedPeak peak = refinePeakNear(spec, j, out.firstOrderWorst[c], [&](double parameter) {
      return weightedAt(parameter, c, 0, stepped.size(), [&](std::size_t d) { return tolerances[d]; });
    });
    out.firstOrderWorst[c] = peak.value;
    out.firstOrderWorstInput[c] = toleranceInputAtParameter(input, spec, peak.parameter);
  }
  return out;
}

}  // namespace linkwright::kinematics
