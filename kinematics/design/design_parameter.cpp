#include "kinematics/design/design_parameter.h"

#include "kinematics/model/driver.h"
#include "kinematics/model/path_shape.h"
#include "kinematics/solve/law_inverse.h"
#include "kinematics/solve/motion_law.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

namespace linkwright::kinematics {
namespace {

// The length of the path the input drives a point along, if it does (and the path is valid).
std::optional<double> drivenPathLength(const Mechanism& m) {
  const std::optional<PointId> driver = driverPoint(m);
  if (!driver) return std::nullopt;
  const auto* path = std::get_if<PathPoint>(&m.points[driver->index].definition);
  if (path == nullptr || checkPathShape(path->path, "path")) return std::nullopt;
  return pathLength(path->path);
}

bool atEnd(double position, double length) { return std::abs(position - length) <= 1e-9 * length; }

void followPathEnd(Design& d, double before, double after) {
  if (atEnd(d.toDeg, before)) d.toDeg = after;
  if (!d.time || !atEnd(motionAt(d.time->law, d.time->toTime).position, before)) return;
  // The new end is looked for from the start over twice the time the old end took, or more
  // in proportion when the path grew: a law at any steady pace reaches it within that.
  TimeBase search = *d.time;
  const double span = d.time->toTime - d.time->fromTime;
  search.toTime = d.time->fromTime + span * std::max(2.0, 2.0 * after / before);
  const std::vector<double> times = timesAtPosition(search, after, 1);
  if (!times.empty()) d.time->toTime = times.front();
}

}  // namespace

bool setDesignParameter(Design& design, const Parameter& parameter, double value) {
  const std::optional<double> before = drivenPathLength(design.mechanism);
  if (!setParameter(design.mechanism, parameter, value)) return false;
  const std::optional<double> after = drivenPathLength(design.mechanism);
  if (before && after && *before > 0.0 && *after != *before) followPathEnd(design, *before, *after);
  return true;
}

}  // namespace linkwright::kinematics
