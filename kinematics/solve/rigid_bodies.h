#pragma once
// The rigid bodies and joints of a linkage, found from its point definitions: what inverse
// dynamics (dynamics/inverse_dynamics.h) writes Newton–Euler equations for and the instant
// centres (analysis/centre_model.h) number. It sits in solve, below both. The Mechanism lists points
// and the links it reports; forces need bodies, so the bars each definition implies are merged:
//
//   Bars. A crank joins its pivot and tip; an actuator's end C joins C to its first point (the
//     actuator between base and C is no bar); a point on a path joins nothing; an RRR point C
//     joins C to each parent; an RRP point joins C to its first point; an RPR point joins the
//     slotted link's pivot and tip; an attached point lies on its link's body; every Link and
//     every DistanceConstraint is a bar.
//   Merging, repeated until nothing changes: two bodies that share two points are one body;
//     three bodies that pairwise share three distinct single points (a triangle of pins) are
//     one rigid body. This finds the ternary plates of a Stephenson II built from constraint
//     triangles. The ground (body 0) holds every GroundPoint and ground guide; a body that
//     merges into it is fixed.
//   Slider blocks are bodies of their own, with a single point, their pin: one per RrpPoint
//     (pinned at C, sliding on its guide's body), one per RprPoint (pinned at `through`,
//     sliding along the slotted link pivot→tip), two per PrpPoint (one on each guide, pinned
//     together at C). A block turns with the body it slides on.
//   Revolute joints. A point held by k bodies gives k − 1 joints, each between the point's hub
//     and one other body. The hub is the ground if the ground holds the point, else the body
//     with the lowest index (bodies are numbered ground first, then in the order their first
//     bar was defined, then the blocks in point order).
//   The driver. Its generalized force is one or two more unknowns (inverse_dynamics.h):
//     a crank's torque T on the body holding its pivot and tip; a linear actuator's axial
//     force f, on the body its link (first→C) lies on at C and, reversed, on the body holding
//     its base at the base (the actuator is a massless two-force member, not a body; its link
//     counts as a bar like an RRR's first bar); a path drive's force F (x and y) on the body
//     holding the driven point, at the point (a massless carriage on the ground path: its
//     tangential part drives, its normal part is the guide's reaction).
//   Gruebler. With n bodies (ground included) and j revolute plus prismatic joints, each joint
//     removing two freedoms, the mobility is M = 3(n − 1) − 2j. Inverse dynamics has
//     2j + d unknowns (two per joint and the driver's d: 1 for a crank or an actuator, 2 for a
//     path drive) and 3(n − 1) equations (three per moving body): square exactly when M = d.
//     A crank or an actuator leaves one freedom to drive (M = 1); a path driver's point is a
//     free end of the linkage, so with the point free it has two (M = 2: the two-link arm's
//     shoulder and elbow), which the path takes both of. bodiesOf refuses any other count,
//     naming it.
//   Serial arm. When a path driver's point P is the far end of an RRR dyad from a ground
//     pivot G (the RRR point E with parents G and P: the arm's shoulder, elbow and tip), the
//     model names G and E, whose joint torques τ = JᵀF inverse dynamics also reports.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// Index of a body in BodyModel::bodies; 0 is the ground.
struct BodyId {
  std::size_t index = 0;
  bool operator==(const BodyId&) const = default;
};

inline constexpr BodyId kGroundBody{0};

enum class BodyKind {
  Ground,  ///< body 0: the frame
  Rigid,   ///< a moving rigid body made of bars (a binary link, a ternary plate, ...)
  Slider,  ///< a slider block
};

/// Which slider block: the point whose definition makes it (an RrpPoint, an RprPoint or a
/// PrpPoint) and, for a PrpPoint, which guide it slides on (0 first, 1 second; else 0).
struct SliderKey {
  PointId point;
  int guide = 0;
  bool operator==(const SliderKey&) const = default;
};

/// One body: the points fixed on it and the links that lie on it.
struct Body {
  BodyKind kind = BodyKind::Rigid;
  std::string name;             ///< "ground", its first link's name, "body3", or "slider_<joint>"
  std::vector<PointId> points;  ///< in point order; a block holds its pin only
  std::vector<LinkId> links;    ///< the Links on it (none for ground and blocks)
  /// Rigid bodies: two of its points a bar apart (its first link's ends if it has a link), from
  /// which its angular velocity and acceleration follow. Blocks: both are the pin.
  PointId reference;
  PointId second;
  SliderKey slider;  ///< blocks only
  BodyId turnsWith;  ///< blocks: the body it slides on (it has the same ω, α)
  bool operator==(const Body&) const = default;
};

/// A pin at `point` between the hub body and `body`. Inverse dynamics solves the force on
/// `body` from `hub` (the hub feels the opposite).
struct RevoluteJoint {
  std::string name;  ///< the point's name, suffixed _<body name> when the point holds several joints
  PointId point;
  BodyId hub;
  BodyId body;
  bool operator==(const RevoluteJoint&) const = default;
};

/// A block sliding on a guide body. Its line at a pose: the guide of the slider's defining
/// point (RRP, PRP), or the slotted link's pivot→tip (RPR); see prismaticDirection.
struct PrismaticJoint {
  std::string name;  ///< the pin's name, then _<RPR point> for a slotted link, _1/_2 for PRP guides
  SliderKey slider;
  PointId pin;  ///< where the block is pinned (C, or an RPR's `through`)
  BodyId block;
  BodyId guide;  ///< the body the block slides on (ground, a link's body, the slotted link)
  bool operator==(const PrismaticJoint&) const = default;
};

enum class DriveKind {
  Crank,     ///< one unknown: the torque on the crank's body from the ground
  Actuator,  ///< one unknown: the actuator's axial force
  Path,      ///< two unknowns: the force of the path drive on the driven point's body
};

/// The driver as inverse dynamics sees it: where its generalized force acts.
struct Drive {
  DriveKind kind = DriveKind::Crank;
  PointId point;  ///< the driver point: the crank tip, the actuator's end C, the point on the path
  PointId pivot;  ///< the crank's pivot, the actuator's base; for a path driver, `point`
  BodyId body;    ///< the driven body: it holds pivot and tip (crank), first and C (actuator), or the point (path)
  BodyId base = kGroundBody;  ///< actuator: the body holding its base, which feels −f; else the ground
  std::string name;           ///< the driver point's name (the force columns' prefix for a path drive)
  bool operator==(const Drive&) const = default;

  /// Unknowns the driver adds: 1 (T or f) or 2 (F's x and y).
  std::size_t unknowns() const { return kind == DriveKind::Path ? 2 : 1; }
};

/// A path driver's point P at the far end of an RRR dyad E from a ground pivot G: a two-link
/// serial chain G–E–P (seed 004's arm: shoulder O, elbow, tip).
struct SerialArm {
  PointId pivot;  ///< G, the shoulder: held by the ground
  PointId elbow;  ///< E, the RRR point whose parents are G and P
  std::string pivotName;
  std::string elbowName;
  bool operator==(const SerialArm&) const = default;
};

/// Bodies and joints of a mechanism, with its Gruebler count.
struct BodyModel {
  std::vector<Body> bodies;  ///< [0] ground, then rigid bodies, then blocks
  std::vector<RevoluteJoint> revolutes;
  std::vector<PrismaticJoint> prismatics;
  std::vector<BodyId> linkBody;  ///< per Mechanism link: the body it lies on
  Drive drive;
  std::optional<SerialArm> arm;  ///< path drivers at the end of a two-link chain from the ground
  /// Where the shaking moment is taken: the crank's pivot, else the first point the ground
  /// holds; none (the world origin) when the ground holds no point.
  std::optional<PointId> momentPoint;
  bool operator==(const BodyModel&) const = default;

  std::size_t movingBodies() const { return bodies.size() - 1; }
  /// Gruebler–Kutzbach mobility 3(n − 1) − 2j: drive.unknowns() for every model bodiesOf returns.
  int mobility() const;
  /// Unknowns of inverse dynamics: 2 per joint and the driver's (1 or 2).
  std::size_t unknowns() const { return 2 * (revolutes.size() + prismatics.size()) + drive.unknowns(); }
  /// Newton–Euler equations: 3 per moving body.
  std::size_t equations() const { return 3 * movingBodies(); }
  /// The block `key` names, if there is one.
  std::optional<BodyId> findSlider(const SliderKey& key) const;
  /// Whether `body` holds `point`.
  bool holds(BodyId body, PointId point) const;
  /// The body a force at `point` is put on: the ground if it holds the point, else the lowest
  /// body that does (the point's hub, as for its revolute joints); none if no body holds it.
  std::optional<BodyId> hubOf(PointId point) const;
};

/// The bodies and joints of a mechanism that checkMechanism accepts. Fails (InvalidStructure)
/// if the driven body is fixed to the ground (the crank, the actuator's link or the path point
/// held by the ground), if an actuator's ends lie on one body or a path point on none, or if
/// unknowns ≠ equations (mobility ≠ the driver's unknowns), naming the count.
Result<BodyModel> bodiesOf(const Mechanism& mechanism);

/// The fixed distance between a link's ends from the definitions (length unit): the crank
/// length, an RRR side, an RRP rod, an RPR slotted link or a constraint.
double linkLength(const Mechanism& mechanism, LinkId link);

/// Unit direction (world frame) along which the block of `joint` slides, at `pose`.
Eigen::Vector2d prismaticDirection(const Mechanism& mechanism, const PrismaticJoint& joint, const Pose& pose);

}  // namespace linkwright::kinematics
