#include "kinematics/synthesis/motion_generation.h"

#include "kinematics/synthesis/placed_fourbar.h"

#include "kinematics/model/fourbar.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics {
namespace {

Error invalid(const std::string& field, const std::string& message) {
  return Error{ErrorCode::InvalidValue, field, message};
}

std::optional<Error> checkPoint(const Eigen::Vector2d& p, const std::string& field) {
  if (auto e = checkCoordinate(p.x(), field + ".x")) return e;
  return checkCoordinate(p.y(), field + ".y");
}

// The size of the task, for relative tolerances.
double taskScale(const std::vector<CouplerPose>& poses, const CirclePoints& c) {
  double s = (c.a - c.b).norm();
  for (const CouplerPose& p : poses) s = std::max({s, (p.point - c.a).norm(), (p.point - c.b).norm()});
  return std::max(s, kMinLength);
}

std::optional<Error> checkTask(const std::vector<CouplerPose>& poses, std::size_t count, const CirclePoints& c) {
  if (poses.size() != count)
    return invalid("poses",
                   "poses must number " + std::to_string(count) + " (got " + std::to_string(poses.size()) + ")");
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const std::string field = "poses[" + std::to_string(i) + "]";
    if (auto e = checkPoint(poses[i].point, field + ".point")) return e;
    if (auto e = checkCoordinate(poses[i].angle, field + ".angle")) return e;
  }
  if (auto e = checkPoint(c.a, "circlePoints.a")) return e;
  if (auto e = checkPoint(c.b, "circlePoints.b")) return e;
  const double scale = taskScale(poses, c);
  for (std::size_t j = 1; j < poses.size(); ++j)
    for (std::size_t i = 0; i < j; ++i)
      if ((poses[j].point - poses[i].point).norm() <= 1e-12 * scale &&
          std::abs(wrapAngle(poses[j].angle - poses[i].angle)) <= 1e-12)
        return invalid("poses[" + std::to_string(j) + "]", "pose " + std::to_string(j + 1) + " equals pose " +
                                                               std::to_string(i + 1) + ": poses must be distinct");
  if ((c.a - c.b).norm() <= 1e-12 * scale)
    return invalid("circlePoints.b",
                   "circlePoints.b must differ from circlePoints.a (the coupler would have no length)");
  return std::nullopt;
}

// Where a coupler point, at p1 in pose 1, is in pose j.
Eigen::Vector2d image(const std::vector<CouplerPose>& poses, std::size_t j, const Eigen::Vector2d& p1) {
  const double turn = poses[j].angle - poses[0].angle;
  const Eigen::Vector2d r = p1 - poses[0].point;
  return poses[j].point + Eigen::Vector2d(std::cos(turn) * r.x() - std::sin(turn) * r.y(),
                                          std::sin(turn) * r.x() + std::cos(turn) * r.y());
}

// The centre of the circle through three points, or nullopt if they are (nearly) collinear.
std::optional<Eigen::Vector2d> circumcentre(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2,
                                            const Eigen::Vector2d& p3) {
  const Eigen::Vector2d b = p2 - p1, c = p3 - p1;
  const double d = 2.0 * cross(b, c);
  const double size = std::max(b.squaredNorm(), c.squaredNorm());
  if (!(std::abs(d) > 1e-12 * size)) return std::nullopt;
  return p1 + Eigen::Vector2d(c.y() * b.squaredNorm() - b.y() * c.squaredNorm(),
                              b.x() * c.squaredNorm() - c.x() * b.squaredNorm()) /
                  d;
}

Branch branchOf(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& o4) {
  return cross(b - a, b - o4) >= 0.0 ? Branch::Open : Branch::Crossed;
}

Result<MotionSynthesis> build(const std::vector<CouplerPose>& poses, const CirclePoints& c, const Eigen::Vector2d& o2,
                              const Eigen::Vector2d& o4, const DefectBounds& bounds, const MotionOptions& options) {
  MotionSynthesis s;
  s.o2 = o2;
  s.o4 = o4;
  for (std::size_t j = 0; j < poses.size(); ++j) {
    s.a.push_back(image(poses, j, c.a));
    s.b.push_back(image(poses, j, c.b));
  }
  const double scale = taskScale(poses, c);
  s.lengths = {(o4 - o2).norm(), (s.a[0] - o2).norm(), (s.b[0] - s.a[0]).norm(), (s.b[0] - o4).norm()};
  if (!(s.lengths.crank > 1e-9 * scale))
    return invalid("circlePoints.a",
                   "circlePoints.a is its own centre point (the poses' rotation pole): the crank "
                   "would have no length");
  if (!(s.lengths.rocker > 1e-9 * scale))
    return invalid("circlePoints.b",
                   "circlePoints.b is its own centre point (the poses' rotation pole): the rocker "
                   "would have no length");
  if (!(s.lengths.frame > 1e-9 * scale))
    return invalid("circlePoints.b", "the two centre points coincide: choose other circle points");
  s.branch = branchOf(s.a[0], s.b[0], o4);
  const double frameAngle = std::atan2(o4.y() - o2.y(), o4.x() - o2.x());
  FourBarTask task{s.lengths, {}, {}, options.needsFullRotation, std::nullopt};
  for (std::size_t j = 0; j < poses.size(); ++j) {
    s.crankAngles.push_back(std::atan2(s.a[j].y() - o2.y(), s.a[j].x() - o2.x()));
    task.crankAngles.push_back(s.crankAngles[j] - frameAngle);
    task.branches.push_back(branchOf(s.a[j], s.b[j], o4));
  }
  const CrankSpan span = crankSpanThrough(s.crankAngles);
  task.workingRange = CrankSpan{span.from - frameAngle, span.to - frameAngle};
  Design d;
  d.kind = "four-bar";
  const Eigen::Vector2d u = (s.b[0] - s.a[0]).normalized();
  const Eigen::Vector2d r = poses[0].point - s.a[0];  // P on the coupler A→B, from A
  d.mechanism = placedFourBar(o2, o4, s.lengths, s.branch, {r.dot(u), cross(u, r)}, options.lengthUnit);
  d.fromDeg = radToDeg(std::min(span.from, span.to));
  d.toDeg = radToDeg(std::max(span.from, span.to));
  d.samples = std::max<std::size_t>(2, samplesEveryHalfDegree(d.fromDeg, d.toDeg));
  if (auto e = checkDesign(d)) return *e;
  FourBarCheck check = checkFourBar(task, bounds);
  s.candidate = {std::move(d), 0.0, check.grashof, check.minTransmission, std::move(check.defects)};
  return s;
}

}  // namespace

Result<MotionSynthesis> synthesiseMotion3(const std::vector<CouplerPose>& poses, const CirclePoints& c,
                                          const DefectBounds& bounds, const MotionOptions& options) {
  if (auto e = checkTask(poses, 3, c)) return *e;
  const auto centreOf = [&](const Eigen::Vector2d& p) {
    return circumcentre(p, image(poses, 1, p), image(poses, 2, p));
  };
  const auto o2 = centreOf(c.a);
  if (!o2)
    return invalid("circlePoints.a",
                   "circlePoints.a's three positions are collinear (or two coincide): it has no "
                   "centre point; choose another circle point");
  const auto o4 = centreOf(c.b);
  if (!o4)
    return invalid("circlePoints.b",
                   "circlePoints.b's three positions are collinear (or two coincide): it has no "
                   "centre point; choose another circle point");
  return build(poses, c, *o2, *o4, bounds, options);
}

Result<MotionSynthesis> synthesiseMotion2(const std::vector<CouplerPose>& poses, const CirclePoints& c, double centreA,
                                          double centreB, const DefectBounds& bounds, const MotionOptions& options) {
  if (auto e = checkTask(poses, 2, c)) return *e;
  if (auto e = checkCoordinate(centreA, "centreA")) return *e;
  if (auto e = checkCoordinate(centreB, "centreB")) return *e;
  const double scale = taskScale(poses, c);
  const auto centreOf = [&](const Eigen::Vector2d& p, double along) -> std::optional<Eigen::Vector2d> {
    const Eigen::Vector2d q = image(poses, 1, p);
    const Eigen::Vector2d chord = q - p;
    if (!(chord.norm() > 1e-12 * scale)) return std::nullopt;
    return 0.5 * (p + q) + along * perp(chord.normalized());
  };
  const auto o2 = centreOf(c.a, centreA);
  if (!o2)
    return invalid("circlePoints.a",
                   "circlePoints.a does not move between the poses (it is their rotation pole): "
                   "choose another circle point");
  const auto o4 = centreOf(c.b, centreB);
  if (!o4)
    return invalid("circlePoints.b",
                   "circlePoints.b does not move between the poses (it is their rotation pole): "
                   "choose another circle point");
  return build(poses, c, *o2, *o4, bounds, options);
}

}  // namespace linkwright::kinematics
