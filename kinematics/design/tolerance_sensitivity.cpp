#include "kinematics/design/tolerance_sensitivity.h"

#include "kinematics/analysis/pose_jet.h"
#include "kinematics/model/units.h"

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

Result<SweepSensitivities> sweepSensitivities(const Mechanism& mechanism, const SweepSpec& spec) {
  auto nominal = sweep(mechanism, spec);
  if (!nominal) return nominal.error();
  SweepSensitivities out;
  out.dimensions = toleranceDimensions(mechanism);
  out.columns = toleranceColumns(mechanism);
  out.sweep = std::move(*nominal);
  const SweepResult& s = out.sweep;
  const std::size_t n = s.size();
  out.derivative.assign(out.columns.size(),
                        std::vector<std::vector<double>>(out.dimensions.size(), std::vector<double>(n, kUndefined)));
  std::vector<Eigen::Vector2d> positions(mechanism.points.size());
  PoseJet jet;
  for (std::size_t d = 0; d < out.dimensions.size(); ++d) {
    const Mechanism stepped = steppedMechanism(mechanism, out.dimensions[d]);
    for (std::size_t j = 0; j < n; ++j) {
      if (!s.assembled(j)) continue;
      for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = s.position[i][j];
      if (!differentiatePose(mechanism, stepped, sweepDriver(spec, j), positions, jet)) continue;
      for (std::size_t c = 0; c < out.columns.size(); ++c)
        if (s.ok(j) || !out.columns[c].isRate()) out.derivative[c][d][j] = derivativeOf(out.columns[c], jet);
    }
  }
  return out;
}

}  // namespace linkwright::kinematics
