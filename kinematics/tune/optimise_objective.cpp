#include "kinematics/tune/optimise_objective.h"

#include "kinematics/analysis/extrema.h"
#include "kinematics/analysis/transmission.h"
#include "kinematics/dynamics/machine_duty.h"
#include "kinematics/model/driver.h"
#include "kinematics/model/number_text.h"
#include "kinematics/model/recognise.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

std::string linkNames(const Mechanism& m) {
  std::string names;
  for (const Link& l : m.links) names += (names.empty() ? "" : ", ") + l.name;
  return names;
}

// The sample's input as the curve's x: the instant on a time base, else the input.
double inputAt(const SweepResult& s, std::size_t j) { return s.time.empty() ? s.inputAngle[j] : s.time[j]; }

std::optional<ObjectiveValue> peakAlpha(const Design& d, const OptimiseObjective& o, const SweepResult& s) {
  const std::size_t link = d.mechanism.findLink(o.link)->index;
  ObjectiveValue v;
  std::vector<bool> valid(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    valid[j] = s.ok(j);
    if (!valid[j]) continue;
    v.curve.x.push_back(inputAt(s, j));
    v.curve.y.push_back(s.linkAlpha[link][j]);
  }
  // Refined between the samples on solved poses (extrema.h), as `extremes` prints it: the
  // design's peak, not its grid's.
  const auto peaks = refineExtrema(d.mechanism, designSweepSpec(d), s.linkAlpha[link], valid,
                                   [&](const Pose& p, double) { return p.linkAlpha[link]; });
  if (!peaks) return std::nullopt;
  v.value = std::max(std::abs(peaks->minimum.value), std::abs(peaks->maximum.value));
  return v;
}

// The worst min(μ, π − μ) over the joints that have a transmission angle, from `angleOf(p)`.
template <typename AngleOf>
double worstTransmissionOf(const Mechanism& m, const AngleOf& angleOf) {
  double worst = kPi;
  for (std::size_t p = 0; p < m.points.size(); ++p)
    if (hasTransmissionAngle(m.points[p].definition)) {
      const double mu = angleOf(p);
      worst = std::min(worst, std::min(mu, kPi - mu));
    }
  return worst;
}

std::optional<ObjectiveValue> transmission(const Design& d, const SweepResult& s) {
  const Mechanism& m = d.mechanism;
  ObjectiveValue v;
  std::vector<double> worst(s.size(), kPi);
  std::vector<bool> valid(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    valid[j] = s.assembled(j);
    if (!valid[j]) continue;
    worst[j] = worstTransmissionOf(m, [&](std::size_t p) { return s.transmissionAngle[p][j]; });
    v.curve.x.push_back(inputAt(s, j));
    v.curve.y.push_back(worst[j]);
  }
  if (v.curve.x.empty()) return std::nullopt;
  // A four-bar's worst over the grid's crank range is exact in closed form (its extremes lie at
  // θ = kπ or at the range's ends); any other linkage's is refined between the samples.
  if (const auto f = asFourBar(m); f && !d.time && s.lockedBetween.empty()) {
    const double shift = f->crankPhase - f->frameAngle;
    if (const auto exact =
            worstTransmissionBetween(f->lengths, s.inputAngle.front() + shift, s.inputAngle.back() + shift)) {
      v.value = *exact;
      return v;
    }
  }
  const auto least = refineMinimum(m, designSweepSpec(d), worst, valid, [&](const Pose& pose, double) {
    return worstTransmissionOf(m, [&](std::size_t p) { return pose.transmissionAngle[p]; });
  });
  if (!least) return std::nullopt;
  v.value = least->value;
  return v;
}

std::optional<ObjectiveValue> path(const Design& d, const OptimiseObjective& o, const SweepResult& s) {
  const std::size_t point = d.mechanism.findPoint(o.point)->index;
  ObjectiveValue v;
  std::vector<bool> valid(s.size());
  for (std::size_t j = 0; j < s.size(); ++j) {
    valid[j] = s.assembled(j);
    if (!valid[j]) continue;
    v.curve.x.push_back(s.position[point][j].x());
    v.curve.y.push_back(s.position[point][j].y());
  }
  if (v.curve.x.empty()) return std::nullopt;
  // Each target's distance from the path is the least |P − target| over the motion: the samples
  // bracket it and it is refined between them, so it is the path's, not a polyline's.
  const SweepSpec spec = designSweepSpec(d);
  double worst = 0.0, squares = 0.0;
  std::vector<double> distance(s.size(), 0.0);
  for (const Eigen::Vector2d& t : o.targets) {
    for (std::size_t j = 0; j < s.size(); ++j)
      if (valid[j]) distance[j] = (s.position[point][j] - t).norm();
    const auto nearest = refineMinimum(d.mechanism, spec, distance, valid,
                                       [&](const Pose& pose, double) { return (pose.position[point] - t).norm(); });
    if (!nearest) return std::nullopt;
    worst = std::max(worst, nearest->value);
    squares += nearest->value * nearest->value;
  }
  v.value = o.measure == PathMeasure::Worst ? worst : std::sqrt(squares / static_cast<double>(o.targets.size()));
  return v;
}

std::optional<ObjectiveValue> rmsTorque(const Design& d) {
  const auto duty = machineDuty(d.mechanism, d.dynamics, designTurn(d), {});
  if (!duty) return std::nullopt;
  return ObjectiveValue{duty->rmsTorque, {duty->angle, duty->torque}};
}

}  // namespace

bool maximised(ObjectiveKind kind) { return kind == ObjectiveKind::Transmission; }

std::string objectiveName(const OptimiseObjective& o) {
  switch (o.kind) {
  case ObjectiveKind::PeakAlpha: return "peak |α| of " + o.link;
  case ObjectiveKind::Transmission: return "worst transmission angle";
  case ObjectiveKind::Path:
    return std::string(o.measure == PathMeasure::Worst ? "worst" : "RMS") + " distance of " + o.point +
           " from the target path";
  case ObjectiveKind::RmsTorque: return "RMS driving torque";
  }
  return "";
}

std::optional<Error> checkObjective(const Design& design, const OptimiseObjective& o) {
  const Mechanism& m = design.mechanism;
  switch (o.kind) {
  case ObjectiveKind::PeakAlpha:
    if (!m.findLink(o.link))
      return invalid("objective.link", "objective.link: the linkage has no link named '" + o.link +
                                           "' (its links: " + linkNames(m) + ")");
    return std::nullopt;
  case ObjectiveKind::Transmission:
    if (std::none_of(m.points.begin(), m.points.end(),
                     [](const Point& p) { return hasTransmissionAngle(p.definition); }))
      return invalid(
          "objective",
          "the linkage has no joint with a transmission angle (an RRR or RRP dyad or an actuator) that could be "
          "improved");
    return std::nullopt;
  case ObjectiveKind::Path: {
    if (!m.findPoint(o.point))
      return invalid("objective.point", "objective.point: the linkage has no point named '" + o.point + "'");
    if (o.targets.empty())
      return invalid("objective.targets", "objective.targets: the target path is empty (give at least one point)");
    for (std::size_t i = 0; i < o.targets.size(); ++i) {
      const std::string field = "objective.targets[" + std::to_string(i) + "]";
      if (auto e = checkCoordinate(o.targets[i].x(), field + ".x")) return e;
      if (auto e = checkCoordinate(o.targets[i].y(), field + ".y")) return e;
    }
    return std::nullopt;
  }
  case ObjectiveKind::RmsTorque:
    if (design.dynamics.links.empty() && design.dynamics.sliders.empty())
      return invalid("dynamics",
                     "the RMS driving torque needs the links' masses, and the design has none "
                     "(give them in the Forces tab or the document's dynamics)");
    if (inputKind(m) != InputKind::Angle)
      return invalid("objective", "the RMS driving torque is a crank's, and this linkage is not driven by a crank");
    return std::nullopt;
  }
  return std::nullopt;
}

std::optional<ObjectiveValue> measureObjective(const Design& design, const OptimiseObjective& o,
                                               const SweepResult& sweep) {
  switch (o.kind) {
  case ObjectiveKind::PeakAlpha: return peakAlpha(design, o, sweep);
  case ObjectiveKind::Transmission: return transmission(design, sweep);
  case ObjectiveKind::Path: return path(design, o, sweep);
  case ObjectiveKind::RmsTorque: return rmsTorque(design);
  }
  return std::nullopt;
}

}  // namespace linkwright::kinematics
