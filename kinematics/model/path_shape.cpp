#include "kinematics/model/path_shape.h"

#include "kinematics/model/number_text.h"
#include "kinematics/model/units.h"
#include "kinematics/model/validate.h"
#include "kinematics/model/vec2.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

struct StateAt {
  double s;

  PathState operator()(const PolylinePath& p) const {
    const std::vector<Eigen::Vector2d>& v = p.vertices;
    // The segment s falls on: the first one before the start, the last one after the end.
    double along = s;
    std::size_t k = 0;
    for (; k + 2 < v.size(); ++k) {
      const double length = (v[k + 1] - v[k]).norm();
      if (along < length) break;
      along -= length;
    }
    const Eigen::Vector2d direction = (v[k + 1] - v[k]).normalized();
    return {v[k] + along * direction, direction, Eigen::Vector2d::Zero()};
  }

  PathState operator()(const ArcPath& a) const {
    const double turn = a.sweep >= 0.0 ? 1.0 : -1.0;
    const double angle = a.startAngle + turn * s / a.radius;
    const Eigen::Vector2d radial(std::cos(angle), std::sin(angle));
    return {a.centre + a.radius * radial, turn * perp(radial), -radial / a.radius};
  }
};

struct LengthOf {
  double operator()(const PolylinePath& p) const {
    double total = 0.0;
    for (std::size_t k = 0; k + 1 < p.vertices.size(); ++k) total += (p.vertices[k + 1] - p.vertices[k]).norm();
    return total;
  }
  double operator()(const ArcPath& a) const { return a.radius * std::abs(a.sweep); }
};

struct Nearest {
  const Eigen::Vector2d& target;

  double operator()(const PolylinePath& p) const {
    double best = 0.0, bestDistance = std::numeric_limits<double>::infinity(), start = 0.0;
    for (std::size_t k = 0; k + 1 < p.vertices.size(); ++k) {
      const Eigen::Vector2d d = p.vertices[k + 1] - p.vertices[k];
      const double length = d.norm();
      const double along = std::clamp(d.dot(target - p.vertices[k]) / length, 0.0, length);
      const double distance = (p.vertices[k] + along / length * d - target).squaredNorm();
      if (distance < bestDistance) {
        bestDistance = distance;
        best = start + along;
      }
      start += length;
    }
    return best;
  }

  double operator()(const ArcPath& a) const {
    const Eigen::Vector2d r = target - a.centre;
    // The angle from the start along the sweep's direction, in [0, 2π); past the arc's end
    // the nearer end wins.
    const double turn = a.sweep >= 0.0 ? 1.0 : -1.0;
    double angle = std::remainder(turn * (std::atan2(r.y(), r.x()) - a.startAngle), 2.0 * kPi);
    if (angle < 0.0) angle += 2.0 * kPi;
    const double sweep = std::abs(a.sweep);
    if (angle > sweep) angle = angle - sweep < 2.0 * kPi - angle ? sweep : 0.0;
    return a.radius * angle;
  }
};

// Where the path crosses the circle |p − c| = radius, as path coordinates within its ends.
struct Crossings {
  const Eigen::Vector2d& c;
  double radius;
  std::vector<double>& out;

  void operator()(const PolylinePath& p) const {
    double start = 0.0;
    for (std::size_t k = 0; k + 1 < p.vertices.size(); ++k) {
      // |a + t·u − c|² = R² with |u| = 1: t² + 2t·u·(a − c) + |a − c|² − R² = 0.
      const Eigen::Vector2d d = p.vertices[k + 1] - p.vertices[k];
      const double length = d.norm();
      const Eigen::Vector2d u = d / length;
      const Eigen::Vector2d w = p.vertices[k] - c;
      const double b = u.dot(w);
      const double disc = b * b - (w.squaredNorm() - radius * radius);
      if (disc >= 0.0)
        for (const double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)})
          if (t >= 0.0 && t <= length) out.push_back(start + t);
      start += length;
    }
  }

  void operator()(const ArcPath& a) const {
    // |m + r·e(φ) − c|² = R²: r·e(φ)·(m − c) = (R² − r² − |m − c|²)/2, i.e. cos(φ − ψ) = k.
    const Eigen::Vector2d w = a.centre - c;
    const double d = w.norm();
    if (!(d > 0.0)) return;  // concentric: the whole arc is in or out
    const double k = (radius * radius - a.radius * a.radius - d * d) / (2.0 * a.radius * d);
    if (k < -1.0 || k > 1.0) return;
    const double psi = std::atan2(w.y(), w.x()) + kPi;  // e(φ) points from m toward c at φ = ψ
    const double turn = a.sweep >= 0.0 ? 1.0 : -1.0;
    for (const double phi : {psi + std::acos(k), psi - std::acos(k)}) {
      double along = std::remainder(turn * (phi - a.startAngle), 2.0 * kPi);
      if (along < 0.0) along += 2.0 * kPi;
      if (along <= std::abs(a.sweep)) out.push_back(a.radius * along);
    }
  }
};

struct CheckShape {
  const std::string& field;

  std::optional<Error> operator()(const PolylinePath& p) const {
    const std::size_t n = p.vertices.size();
    if (n < 2)
      return Error{ErrorCode::InvalidStructure, field + ".vertices",
                   field + ".vertices needs at least two points (got " + std::to_string(n) + ")"};
    for (std::size_t k = 0; k < n; ++k) {
      const std::string vertex = field + ".vertices[" + std::to_string(k) + "]";
      if (auto e = checkCoordinate(p.vertices[k].x(), vertex + ".x")) return e;
      if (auto e = checkCoordinate(p.vertices[k].y(), vertex + ".y")) return e;
      if (k > 0 && !((p.vertices[k] - p.vertices[k - 1]).norm() >= kMinLength))
        return Error{ErrorCode::InvalidValue, vertex,
                     vertex + " must be at least " + formatNumber(kMinLength) +
                         " from the vertex before it (a segment needs a direction)"};
    }
    return std::nullopt;
  }

  std::optional<Error> operator()(const ArcPath& a) const {
    if (auto e = checkCoordinate(a.centre.x(), field + ".centre.x")) return e;
    if (auto e = checkCoordinate(a.centre.y(), field + ".centre.y")) return e;
    if (auto e = checkLength(a.radius, field + ".radius", "radius")) return e;
    if (auto e = checkCoordinate(a.startAngle, field + ".startAngle")) return e;
    if (!(a.sweep != 0.0 && std::abs(a.sweep) <= 2.0 * kPi))
      return Error{ErrorCode::InvalidValue, field + ".sweep",
                   field + ".sweep must be non-zero and within ±360° (got " + formatNumber(radToDeg(a.sweep)) + "°)"};
    return std::nullopt;
  }
};

}  // namespace

PathState pathAt(const PathShape& shape, double s) { return std::visit(StateAt{s}, shape); }

double nearestPathCoordinate(const PathShape& shape, const Eigen::Vector2d& target) {
  return std::visit(Nearest{target}, shape);
}

std::vector<std::pair<double, double>> pathOutsideAnnulus(const PathShape& shape, const Eigen::Vector2d& centre,
                                                          double inner, double outer) {
  std::vector<double> cuts{0.0, pathLength(shape)};
  for (const double radius : {inner, outer}) std::visit(Crossings{centre, radius, cuts}, shape);
  std::sort(cuts.begin(), cuts.end());
  std::vector<std::pair<double, double>> outside;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (!(cuts[i + 1] > cuts[i])) continue;
    const double reach = (pathAt(shape, 0.5 * (cuts[i] + cuts[i + 1])).point - centre).norm();
    if (reach >= inner && reach <= outer) continue;
    if (!outside.empty() && outside.back().second == cuts[i]) outside.back().second = cuts[i + 1];
    else outside.emplace_back(cuts[i], cuts[i + 1]);
  }
  return outside;
}

double pathLength(const PathShape& shape) { return std::visit(LengthOf{}, shape); }

std::optional<Error> checkPathShape(const PathShape& shape, const std::string& field) {
  return std::visit(CheckShape{field}, shape);
}

}  // namespace linkwright::kinematics
