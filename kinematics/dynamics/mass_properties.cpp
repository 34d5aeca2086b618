#include "kinematics/dynamics/mass_properties.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/validate.h"
#include "kinematics/solve/rigid_bodies.h"

#include <cmath>
#include <set>
#include <variant>

namespace linkwright::kinematics {
namespace {

Error valueError(const std::string& field, const std::string& why) {
  return Error{ErrorCode::InvalidValue, field, field + " " + why};
}

std::optional<Error> checkMass(double value, const std::string& field) {
  return checkNonNegative(value, field, kMaxMass, "kg");
}

std::optional<Error> checkInertia(double value, const std::string& field) {
  return checkNonNegative(value, field, kMaxInertia, "kg·m²");
}

std::optional<Error> checkVector(const Eigen::Vector2d& v, const std::string& field, double max,
                                 const std::string& unit) {
  if (auto e = checkMagnitude(v.x(), field + ".x", max, unit)) return e;
  return checkMagnitude(v.y(), field + ".y", max, unit);
}

std::optional<Error> checkLinkName(const Mechanism& m, const std::string& name, const std::string& field) {
  if (m.findLink(name)) return std::nullopt;
  return valueError(field, "names no link of this mechanism (got \"" + name + "\")");
}

bool isSliderPoint(const PointDefinition& def) {
  return std::holds_alternative<RrpPoint>(def) || std::holds_alternative<RprPoint>(def) ||
         std::holds_alternative<PrpPoint>(def);
}

// A slider named by its defining point and, for a prp point, its guide.
std::optional<Error> checkSliderKey(const Mechanism& m, const std::string& point, int guide, const std::string& field) {
  const auto id = m.findPoint(point);
  if (!id) return valueError(field + ".point", "names no point of this mechanism (got \"" + point + "\")");
  const PointDefinition& def = m.points[id->index].definition;
  // The path drive's carriage is not a body of the model (rigid_bodies.h): it carries nothing.
  if (std::holds_alternative<PathPoint>(def))
    return valueError(field + ".point", "must name a slider's point (an rrp, rpr or prp point; got \"" + point +
                                            "\", which is driven along a path: its carriage is massless and takes "
                                            "no load; put the mass or load on a link that holds " +
                                            point + ")");
  if (!isSliderPoint(def))
    return valueError(field + ".point", "must name a slider's point (an rrp, rpr or prp point; got \"" + point + "\")");
  const int guides = std::holds_alternative<PrpPoint>(def) ? 2 : 1;
  if (guide < 0 || guide >= guides)
    return valueError(field + ".guide", "must be " + std::string(guides == 2 ? "0 or 1" : "0") + " for " + point +
                                            " (got " + std::to_string(guide) + ")");
  return std::nullopt;
}

std::optional<Error> checkLinkMasses(const Mechanism& m, const std::vector<LinkMass>& links) {
  std::set<std::string> seen;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const LinkMass& l = links[k];
    const std::string field = "links[" + std::to_string(k) + "]";
    if (auto e = checkLinkName(m, l.link, field + ".link")) return e;
    if (!seen.insert(l.link).second) return valueError(field + ".link", "repeats the link \"" + l.link + "\"");
    if (auto e = checkMass(l.mass, field + ".mass")) return e;
    if (l.centre) {
      if (auto e = checkCoordinate(l.centre->along, field + ".centre.along")) return e;
      if (auto e = checkCoordinate(l.centre->across, field + ".centre.across")) return e;
    }
    if (l.inertia)
      if (auto e = checkInertia(*l.inertia, field + ".inertia")) return e;
  }
  return std::nullopt;
}

std::optional<Error> checkSliderMasses(const Mechanism& m, const std::vector<SliderMass>& sliders) {
  std::set<std::pair<std::string, int>> seen;
  for (std::size_t k = 0; k < sliders.size(); ++k) {
    const SliderMass& s = sliders[k];
    const std::string field = "sliders[" + std::to_string(k) + "]";
    if (auto e = checkSliderKey(m, s.point, s.guide, field)) return e;
    if (!seen.insert({s.point, s.guide}).second)
      return valueError(field + ".point", "repeats the slider \"" + s.point + "\"");
    if (auto e = checkMass(s.mass, field + ".mass")) return e;
    if (auto e = checkInertia(s.inertia, field + ".inertia")) return e;
  }
  return std::nullopt;
}

std::optional<Error> checkForce(const Mechanism& m, const PointForce& f, const std::string& field) {
  if (auto e = checkVector(f.force, field + ".force", kMaxForce, "N")) return e;
  if (f.link.empty()) return checkSliderKey(m, f.point, f.guide, field);
  if (auto e = checkLinkName(m, f.link, field + ".link")) return e;
  const auto point = m.findPoint(f.point);
  if (!point) return valueError(field + ".point", "names no point of this mechanism (got \"" + f.point + "\")");
  // A mechanism whose bodies cannot be found fails when forces are solved, with its own reason.
  const auto bodies = bodiesOf(m);
  if (bodies && !bodies->holds(bodies->linkBody[m.findLink(f.link)->index], *point))
    return valueError(field + ".point", "must lie on the body of link " + f.link + " (got \"" + f.point + "\")");
  return std::nullopt;
}

std::optional<Error> checkSpringEnd(const Mechanism& m, const SpringEnd& end, const std::string& field) {
  const auto point = m.findPoint(end.point);
  if (!point) return valueError(field + ".point", "names no point of this mechanism (got \"" + end.point + "\")");
  if (end.link.empty()) {
    if (!std::holds_alternative<GroundPoint>(m.points[point->index].definition))
      return valueError(field + ".point", "must be a ground point for an end on the frame (got \"" + end.point + "\")");
    return std::nullopt;
  }
  if (auto e = checkLinkName(m, end.link, field + ".link")) return e;
  const auto bodies = bodiesOf(m);
  if (bodies && !bodies->holds(bodies->linkBody[m.findLink(end.link)->index], *point))
    return valueError(field + ".point", "must lie on the body of link " + end.link + " (got \"" + end.point + "\")");
  return std::nullopt;
}

std::optional<Error> checkSpring(const Mechanism& m, const Spring& s, const std::string& field) {
  if (auto e = checkSpringEnd(m, s.first, field + ".first")) return e;
  if (auto e = checkSpringEnd(m, s.second, field + ".second")) return e;
  if (!(s.stiffness >= 0.0 && s.stiffness <= kMaxStiffness))
    return valueError(field + ".stiffness", "must be between 0 and 1e15 N/m (got " + formatNumber(s.stiffness) + ")");
  if (!(s.freeLength >= 0.0 && s.freeLength <= kMaxLength))
    return valueError(field + ".freeLength", "must be between 0 and 1e9 (got " + formatNumber(s.freeLength) + ")");
  return checkMagnitude(s.preload, field + ".preload", kMaxForce, "N");
}

}  // namespace

bool LinkageDynamics::empty() const {
  return links.empty() && sliders.empty() && !loads.gravity && loads.torques.empty() && loads.forces.empty() &&
         loads.springs.empty();
}

std::optional<Error> checkDynamics(const Mechanism& m, const LinkageDynamics& d) {
  if (auto e = checkLinkMasses(m, d.links)) return e;
  if (auto e = checkSliderMasses(m, d.sliders)) return e;
  if (d.loads.gravity)
    if (auto e = checkVector(*d.loads.gravity, "loads.gravity", kMaxGravity, "m/s²")) return e;
  for (std::size_t k = 0; k < d.loads.torques.size(); ++k) {
    const std::string field = "loads.torques[" + std::to_string(k) + "]";
    if (auto e = checkLinkName(m, d.loads.torques[k].link, field + ".link")) return e;
    if (auto e = checkMagnitude(d.loads.torques[k].torque, field + ".torque", kMaxTorque, "N·m")) return e;
  }
  for (std::size_t k = 0; k < d.loads.forces.size(); ++k)
    if (auto e = checkForce(m, d.loads.forces[k], "loads.forces[" + std::to_string(k) + "]")) return e;
  for (std::size_t k = 0; k < d.loads.springs.size(); ++k)
    if (auto e = checkSpring(m, d.loads.springs[k], "loads.springs[" + std::to_string(k) + "]")) return e;
  return std::nullopt;
}

Eigen::Vector2d massCentreAt(const LinkMass& mass, const Eigen::Vector2d& first, const Eigen::Vector2d& second) {
  const Eigen::Vector2d e = second - first;
  const double length = e.norm();
  if (!mass.centre || length == 0.0) return first + 0.5 * e;
  const Eigen::Vector2d u = e / length;
  return first + mass.centre->along * u + mass.centre->across * Eigen::Vector2d(-u.y(), u.x());
}

}  // namespace linkwright::kinematics
