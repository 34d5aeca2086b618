#include "kinematics/analysis/extrema.h"

#include "kinematics/model/units.h"
#include "kinematics/solve/golden_section.h"
#include "kinematics/solve/pose_solver.h"

#include <cmath>

namespace linkwright::kinematics {
namespace {

// Golden-section search for the maximum of `sign`·f on [lo, hi] (of the sweep's parameter);
// returns the best extremum among the ends and the interior points it visited.
struct Search {
  const Mechanism& mechanism;
  const SweepSpec& spec;
  const PoseQuantity& quantity;
  Pose pose;

  std::optional<double> evaluate(double parameter) {
    const DriverState driver = sweepDriverAt(spec, parameter);
    const PoseReport r = solvePoseInto(mechanism, driver, {true, true}, pose);
    if (r.status != PoseStatus::Ok) return std::nullopt;
    return quantity(pose, driver.position);
  }

  Extremum at(double value, double parameter, bool refined) const {
    if (!spec.time) return {value, parameter, refined};
    return {value, sweepDriverAt(spec, parameter).position, refined, parameter};
  }

  Extremum maximize(double lo, double hi, double sign, const Extremum& start, double tolerance) {
    // Every pose the search solves counts: the best of them is the extremum.
    Extremum best = start;
    auto consider = [&](double parameter) {
      const std::optional<double> v = evaluate(parameter);
      if (v && sign * *v > sign * best.value) best = at(*v, parameter, true);
      return v ? sign * *v : -INFINITY;
    };
    (void)goldenSectionMaximum(consider, lo, hi, tolerance);
    return best;
  }
};

}  // namespace

void SampledExtrema::add(std::size_t index, bool valid, double value) {
  for (std::optional<Best>* best : {&m_lowest, &m_highest})
    if (*best && (*best)->index + 1 == index) (*best)->validAfter = valid;
  if (valid && (!m_lowest || value < m_lowest->value)) m_lowest = Best{index, value, m_lastValid, false};
  if (valid && (!m_highest || value > m_highest->value)) m_highest = Best{index, value, m_lastValid, false};
  if (index == 1) m_secondValid = valid;
  m_lastButOneValid = m_lastValid;
  m_lastValid = valid;
  m_samples = index + 1;
}

namespace {

// refineExtrema, the maximum's search left out (its sample kept) unless `maximumToo`.
std::optional<Extrema> refine(const Mechanism& mechanism, const SweepSpec& spec, const SampledExtrema& sampled,
                              const PoseQuantity& quantity, double angleTolerance, bool maximumToo) {
  if (!sampled.lowest()) return std::nullopt;
  Search search{mechanism, spec, quantity, {}};
  preparePose(mechanism, search.pose);
  // The bracket: from the best sample's valid neighbours (or the sample itself at an end). Over
  // a full turn the ends are neighbours too: an extremum just before the first sample is one
  // just before the last.
  const std::size_t n = sampled.samples();
  const bool fullTurn = !spec.time && n > 2 && std::abs(std::abs(spec.toAngle - spec.fromAngle) - 2.0 * kPi) < 1e-9;
  const double step = n > 1 ? sweepParameter(spec, 1) - sweepParameter(spec, 0) : 0.0;
  auto bracket = [&](const SampledExtrema::Best& best) {
    const std::size_t j = best.index;
    double lo = sweepParameter(spec, j);
    double hi = lo;
    if (j > 0 && best.validBefore) lo = sweepParameter(spec, j - 1);
    else if (j == 0 && fullTurn && sampled.lastButOneValid()) lo -= step;
    if (j + 1 < n && best.validAfter) hi = sweepParameter(spec, j + 1);
    else if (j + 1 == n && fullTurn && sampled.secondValid()) hi += step;
    return std::pair{std::min(lo, hi), std::max(lo, hi)};
  };
  const SampledExtrema::Best& lowest = *sampled.lowest();
  const SampledExtrema::Best& highest = *sampled.highest();
  Extrema out;
  const auto [minLo, minHi] = bracket(lowest);
  out.minimum = search.maximize(minLo, minHi, -1.0, search.at(lowest.value, sweepParameter(spec, lowest.index), false),
                                angleTolerance);
  const auto [maxLo, maxHi] = maximumToo ? bracket(highest) : std::pair{1.0, 0.0};
  out.maximum = search.at(highest.value, sweepParameter(spec, highest.index), false);
  if (maximumToo) out.maximum = search.maximize(maxLo, maxHi, 1.0, out.maximum, angleTolerance);
  if (spec.time) return out;
  // Report angles inside the requested range (a full-turn bracket may step just outside it).
  for (Extremum* e : {&out.minimum, &out.maximum}) {
    const double lowEnd = std::min(spec.fromAngle, spec.toAngle);
    const double highEnd = std::max(spec.fromAngle, spec.toAngle);
    if (e->inputAngle < lowEnd) e->inputAngle += 2.0 * kPi;
    if (e->inputAngle > highEnd) e->inputAngle -= 2.0 * kPi;
  }
  return out;
}

SampledExtrema sampledOf(const std::vector<double>& values, const std::vector<bool>& valid) {
  SampledExtrema sampled;
  for (std::size_t j = 0; j < values.size(); ++j) sampled.add(j, valid[j], values[j]);
  return sampled;
}

}  // namespace

std::optional<Extrema> refineExtrema(const Mechanism& mechanism, const SweepSpec& spec, const SampledExtrema& sampled,
                                     const PoseQuantity& quantity, double angleTolerance) {
  return refine(mechanism, spec, sampled, quantity, angleTolerance, true);
}

std::optional<Extrema> refineExtrema(const Mechanism& mechanism, const SweepSpec& spec,
                                     const std::vector<double>& values, const std::vector<bool>& valid,
                                     const PoseQuantity& quantity, double angleTolerance) {
  return refine(mechanism, spec, sampledOf(values, valid), quantity, angleTolerance, true);
}

std::optional<Extremum> refineMinimum(const Mechanism& mechanism, const SweepSpec& spec,
                                      const std::vector<double>& values, const std::vector<bool>& valid,
                                      const PoseQuantity& quantity, double angleTolerance) {
  const auto extrema = refine(mechanism, spec, sampledOf(values, valid), quantity, angleTolerance, false);
  if (!extrema) return std::nullopt;
  return extrema->minimum;
}

}  // namespace linkwright::kinematics
