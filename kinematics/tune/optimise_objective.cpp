#include "kinematics/tune/optimise_objective.h"

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

std::optional<ObjectiveValue> peakAlpha(const Mechanism& m, const OptimiseObjective& o, const SweepResult& s) {
  const std::size_t link = m.findLink(o.link)->index;
  ObjectiveValue v;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.ok(j)) continue;
    v.curve.x.push_back(inputAt(s, j));
    v.curve.y.push_back(s.linkAlpha[link][j]);
    v.value = std::max(v.value, std::abs(s.linkAlpha[link][j]));
  }
  if (v.curve.x.empty()) return std::nullopt;
  return v;
}

std::optional<ObjectiveValue> transmission(const Design& d, const SweepResult& s) {
  const Mechanism& m = d.mechanism;
  ObjectiveValue v;
  v.value = kPi;
  for (std::size_t j = 0; j < s.size(); ++j) {
    if (!s.assembled(j)) continue;
    double worst = kPi;
    for (std::size_t p = 0; p < m.points.size(); ++p)
      if (hasTransmissionAngle(m.points[p].definition) && !s.transmissionAngle[p].empty()) {
        const double mu = s.transmissionAngle[p][j];
        worst = std::min(worst, std::min(mu, kPi - mu));
      }
    v.curve.x.push_back(inputAt(s, j));
    v.curve.y.push_back(worst);
    v.value = std::min(v.value, worst);
  }
  if (v.curve.x.empty()) return std::nullopt;
  // A four-bar's worst over the grid's crank range is exact (its extremes lie at θ = kπ or at
  // the range's ends), not the samples' worst.
  if (const auto f = asFourBar(m); f && !d.time && s.lockedBetween.empty()) {
    const double shift = f->crankPhase - f->frameAngle;
    if (const auto exact =
            worstTransmissionBetween(f->lengths, s.inputAngle.front() + shift, s.inputAngle.back() + shift))
      v.value = *exact;
  }
  return v;
}

std::optional<ObjectiveValue> path(const Mechanism& m, const OptimiseObjective& o, const SweepResult& s) {
  const std::size_t point = m.findPoint(o.point)->index;
  ObjectiveValue v;
  std::vector<Eigen::Vector2d> curve;
  for (std::size_t j = 0; j < s.size(); ++j)
    if (s.assembled(j)) {
      curve.push_back(s.position[point][j]);
      v.curve.x.push_back(curve.back().x());
      v.curve.y.push_back(curve.back().y());
    }
  if (curve.empty()) return std::nullopt;
  double worst = 0.0, squares = 0.0;
  for (const Eigen::Vector2d& t : o.targets) {
    const double distance = distanceFromPolyline(t, curve);
    worst = std::max(worst, distance);
    squares += distance * distance;
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
  case ObjectiveKind::PeakAlpha: return peakAlpha(design.mechanism, o, sweep);
  case ObjectiveKind::Transmission: return transmission(design, sweep);
  case ObjectiveKind::Path: return path(design.mechanism, o, sweep);
  case ObjectiveKind::RmsTorque: return rmsTorque(design);
  }
  return std::nullopt;
}

double distanceFromPolyline(const Eigen::Vector2d& target, const std::vector<Eigen::Vector2d>& path) {
  double best = (target - path.front()).norm();
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1];
    const Eigen::Vector2d ab = path[i] - a;
    const double squared = ab.squaredNorm();
    const double t = squared > 0.0 ? std::clamp((target - a).dot(ab) / squared, 0.0, 1.0) : 0.0;
    best = std::min(best, (target - (a + t * ab)).norm());
  }
  return best;
}

}  // namespace linkwright::kinematics
