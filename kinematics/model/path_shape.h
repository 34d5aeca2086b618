#pragma once
// Where a driven point is at path coordinate s, and how it moves: the position p(s), the unit
// tangent p'(s) and the curvature vector p''(s). A point driven along the path at ṡ, s̈ then
// has v = ṡ·p' and a = s̈·p' + ṡ²·p'', exactly.
//
// A polyline's s is the arc length from its first vertex: p' is the segment's direction and
// p'' is zero; at a vertex the direction turns at once, so ṡ·p' jumps there (the point takes
// the corner at full speed). Before the first vertex and after the last the line goes on along
// the end segment. An arc's s runs from its start along its sweep (arc length), and before
// and after the arc the point goes on around its circle.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace linkwright::kinematics {

struct PathState {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();      ///< p(s)
  Eigen::Vector2d tangent = Eigen::Vector2d::Zero();    ///< p'(s), a unit vector
  Eigen::Vector2d curvature = Eigen::Vector2d::Zero();  ///< p''(s), per length unit
};

/// The path at coordinate `s` (length unit). The shape must be valid (checkPathShape).
PathState pathAt(const PathShape& shape, double s);

/// The coordinate s of the point of the path (between its ends) nearest `target`.
double nearestPathCoordinate(const PathShape& shape, const Eigen::Vector2d& target);

/// The stretches of the path between its ends that lie outside the annulus about `centre`
/// with radii `inner` ≤ `outer`, as (from, to) path coordinates in increasing order: where a
/// point driven along the path cannot be reached by two links of lengths l1 and l2 from a
/// pivot at `centre` (inner = |l1 − l2|, outer = l1 + l2). Exact: the crossings are roots of
/// a quadratic on each segment, of a cosine on an arc.
std::vector<std::pair<double, double>> pathOutsideAnnulus(const PathShape& shape, const Eigen::Vector2d& centre,
                                                          double inner, double outer);

/// The path's length from its start to its end (length unit).
double pathLength(const PathShape& shape);

/// Error naming `field` and the value unless the shape can be followed: a polyline of at least
/// two vertices, consecutive ones distinct, coordinates within the input domain; an arc with a
/// valid radius and a sweep that is non-zero and at most one turn either way.
std::optional<Error> checkPathShape(const PathShape& shape, const std::string& field);

}  // namespace linkwright::kinematics
