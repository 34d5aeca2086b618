#pragma once
// The mechanism description: a planar linkage as an ordered list of points, each defined
// from points before it (ground pivot, driven crank tip, RRR dyad joint, point fixed on a
// link), and the moving links whose angles, rates and accelerations are reported. This is the
// dyad decomposition of Pyslvs and of every closed-form textbook method: solving the points in
// order solves the linkage. One driver moves it (one degree of freedom): a crank, a point driven
// along a path, or a linear actuator (driver.h names its coordinate). RRP dyads (sliders on
// a guide) make slider-cranks; RPR dyads (slotted links) make quick-return mechanisms; PRP
// dyads join two sliders. Six-bars are a four-bar plus one more dyad.
//
// Frame and units: x to the right, y up, angles counter-clockwise from +x in radians. For a
// four-bar, +x is the frame line (crank pivot to rocker pivot). Lengths are in
// Mechanism::lengthUnit; velocities in that unit per second.

#include "kinematics/model/ids.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace linkwright::kinematics {

/// Assembly branch of an RRR dyad. Open: the dyad joint C lies to the left of the line from
/// its first parent P1 to its second parent P2, i.e. (C−P1)×(C−P2) > 0. For a four-bar with
/// P1 = crank tip B and P2 = rocker pivot O4 this is sin(θ_rocker − θ_coupler) > 0, the
/// configuration the thesis draws. Crossed is the mirror image about P1P2.
enum class Branch { Open, Crossed };

/// A pivot fixed to the ground at `position` (length unit).
struct GroundPoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  bool operator==(const GroundPoint&) const = default;
};

/// The driven crank tip: at `length` from ground point `pivot`, at the input angle plus
/// `phase` (rad). The input is the crank's angle (rad).
struct CrankPoint {
  PointId pivot;
  double length = 1.0;
  double phase = 0.0;
  bool operator==(const CrankPoint&) const = default;
};

/// A path fixed to the ground, by its vertices, straight between them. Its coordinate s is the
/// arc length from the first vertex (length unit); beyond the ends the path goes on straight
/// along its end segments. Two vertices make a line segment (a slider's guide); a table of
/// points makes a polyline.
struct PolylinePath {
  std::vector<Eigen::Vector2d> vertices;
  bool operator==(const PolylinePath&) const = default;
};

/// A circular arc fixed to the ground: centre, radius, the angle where s = 0 (rad, CCW from
/// +x) and the sweep (rad; positive runs counter-clockwise). s is the arc length from the
/// start, signed along the sweep; beyond the ends the path goes on around its circle.
struct ArcPath {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 1.0;
  double startAngle = 0.0;
  double sweep = 1.0;
  bool operator==(const ArcPath&) const = default;
};

using PathShape = std::variant<PolylinePath, ArcPath>;

/// A point driven along a ground path (a tool tip following a line, a piston on its bore):
/// the input is its path coordinate s (length unit, path_shape.h).
struct PathPoint {
  PathShape path;
  bool operator==(const PathPoint&) const = default;
};

/// The far end C of a linear actuator (a hydraulic cylinder pinned at ground or link point
/// `base`): at `length` from point `first` (on the link it drives) and at the input distance
/// from `base`, on the side given by `branch` (as an RRR point's, with `base` second). The
/// input is the actuator's length, pin to pin (length unit).
struct ActuatorPoint {
  PointId first;
  double length = 1.0;
  PointId base;
  Branch branch = Branch::Open;
  bool operator==(const ActuatorPoint&) const = default;
};

/// The joint C of an RRR dyad: at `firstLength` from point `first` and at `secondLength` from
/// point `second`, on the side given by `branch`.
struct RrrPoint {
  PointId first;
  double firstLength = 1.0;
  PointId second;
  double secondLength = 1.0;
  Branch branch = Branch::Open;
  bool operator==(const RrrPoint&) const = default;
};

/// A straight guide line fixed in a body: the ground when `link` is empty, else a moving link.
/// On the ground, `point` is a position and `angle` is absolute (rad, CCW from +x). On a link,
/// `point` is (along, across) from the link's first point in the link's frame (as for an
/// AttachedPoint) and `angle` is measured from the link's direction.
struct Guide {
  std::optional<LinkId> link;
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  double angle = 0.0;
  bool operator==(const Guide&) const = default;
};

/// The joint C of an RRP dyad (a slider): at `length` from point `first`, on the straight
/// `guide` (fixed to the ground, or to a link: a slider on a moving bar). Branch::Open puts C
/// at the larger guide coordinate (further along the guide's direction), Crossed at the
/// smaller one.
struct RrpPoint {
  PointId first;
  double length = 1.0;
  Guide guide;
  Branch branch = Branch::Open;
  bool operator==(const RrpPoint&) const = default;
};

/// The tip of a slotted link (an RPR dyad): the link turns about `pivot` and its slot slides
/// through the block pinned at `through` (a crank pin, say); the point lies on the slot's
/// line at `length` from the pivot, on the side of `through`. The quick-return shaper's
/// rocker is one.
struct RprPoint {
  PointId pivot;
  PointId through;
  double length = 1.0;
  bool operator==(const RprPoint&) const = default;
};

/// The joint C of a PRP dyad: a pin joining two sliders, each on its own straight guide, so C
/// is where the two guide lines cross (e.g. a block sliding on a rocker whose pin runs in a
/// ground slot). There is one solution; parallel guides cannot be assembled.
struct PrpPoint {
  Guide first;
  Guide second;
  bool operator==(const PrpPoint&) const = default;
};

/// A point rigidly fixed on a link: `along` the link's direction (from its first point toward
/// its second) and `across` it (90° counter-clockwise), measured from the link's first point.
struct AttachedPoint {
  LinkId link;
  double along = 0.0;
  double across = 0.0;
  bool operator==(const AttachedPoint&) const = default;
};

/// A point with no closed-form definition: found, together with the other free points next to
/// it in the list, by Newton–Raphson on the distance constraints (Mechanism::constraints) that
/// reach it. This solves loops that do not split into dyads (a triad, e.g. a Stephenson II
/// six-bar). `guess` is its position in the assembly the user means (length unit): the first
/// solve starts there, so it picks the branch; later solves start from the previous pose.
struct FreePoint {
  Eigen::Vector2d guess = Eigen::Vector2d::Zero();
  bool operator==(const FreePoint&) const = default;
};

using PointDefinition = std::variant<GroundPoint, CrankPoint, PathPoint, ActuatorPoint, RrrPoint, RrpPoint, RprPoint,
                                     PrpPoint, AttachedPoint, FreePoint>;

/// True for the points solved as one of two mirror-image candidates, whose branch a sweep
/// tracks and whose transmission angle and assembly gap a pose reports: RRR and RRP dyads and
/// linear actuators.
inline bool hasAssemblyBranch(const PointDefinition& d) {
  return std::holds_alternative<RrrPoint>(d) || std::holds_alternative<RrpPoint>(d) ||
         std::holds_alternative<ActuatorPoint>(d);
}

/// A named point. Its definition refers only to points (and links) defined before it.
struct Point {
  std::string name;
  PointDefinition definition;
  bool operator==(const Point&) const = default;
};

/// A moving rigid link between two points that its definition keeps at constant distance
/// (crank pivot and tip, a dyad joint and one of its parents, an actuator's end and `first`). Its angle is the direction
/// from `first` to `second`.
struct Link {
  std::string name;
  PointId first;
  PointId second;
  bool operator==(const Link&) const = default;
};

/// Points `first` and `second` held `length` apart (length unit): a rigid bar, or one side of
/// a rigid plate. Only free points use these; every constraint must reach a free point.
struct DistanceConstraint {
  PointId first;
  PointId second;
  double length = 1.0;
  bool operator==(const DistanceConstraint&) const = default;
};

/// A complete linkage description. A regular value: copy, compare, store.
struct Mechanism {
  std::string lengthUnit = "mm";
  std::vector<Point> points;
  std::vector<Link> links;
  std::vector<DistanceConstraint> constraints;  ///< for free points only
  bool operator==(const Mechanism&) const = default;

  /// The id of the point named `name`, if any.
  std::optional<PointId> findPoint(const std::string& name) const;
  /// The id of the link named `name`, if any.
  std::optional<LinkId> findLink(const std::string& name) const;
};

/// True for the joints that have a transmission angle: the points hasAssemblyBranch names (RRR
/// and RRP dyads, and linear actuators, whose angle is the one at the rod's end between the rod
/// and the link it drives). The one rule: the sweep's columns and the CSV, the plots and readouts,
/// classify and the optimiser all take their joints from here.
inline bool hasTransmissionAngle(const PointDefinition& d) { return hasAssemblyBranch(d); }

/// The indices of the points with a transmission angle (hasTransmissionAngle), in point order.
std::vector<std::size_t> transmissionJoints(const Mechanism& m);

}  // namespace linkwright::kinematics
