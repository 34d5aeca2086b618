#pragma once
// The rigid bodies and joints of a linkage, found from its point definitions: what inverse
// dynamics (inverse_dynamics.h) writes Newton–Euler equations for. The Mechanism lists points
// and the links it reports; forces need bodies, so the bars each definition implies are merged:
//
//   Bars. A crank joins its pivot and tip; an RRR point C joins C to each parent; an RRP point
//     joins C to its first point; an RPR point joins the slotted link's pivot and tip; an
//     attached point lies on its link's body; every Link and every DistanceConstraint is a bar.
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
//   Gruebler. With n bodies (ground included) and j revolute plus prismatic joints, each joint
//     removing two freedoms, the mobility is M = 3(n − 1) − 2j. Inverse dynamics has
//     2j + 1 unknowns (two per joint and the driving torque) and 3(n − 1) equations (three per
//     moving body): square exactly when M = 1. bodiesOf refuses any other count, naming it.

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

/// Bodies and joints of a mechanism, with its Gruebler count.
struct BodyModel {
  std::vector<Body> bodies;  ///< [0] ground, then rigid bodies, then blocks
  std::vector<RevoluteJoint> revolutes;
  std::vector<PrismaticJoint> prismatics;
  std::vector<BodyId> linkBody;  ///< per Mechanism link: the body it lies on
  BodyId driven;                 ///< the body holding the crank pivot and tip
  PointId crankPivot;
  PointId crankTip;
  bool operator==(const BodyModel&) const = default;

  std::size_t movingBodies() const { return bodies.size() - 1; }
  /// Gruebler–Kutzbach mobility 3(n − 1) − 2j (1 for every model bodiesOf returns).
  int mobility() const;
  /// Unknowns of inverse dynamics: 2 per joint and the driving torque.
  std::size_t unknowns() const { return 2 * (revolutes.size() + prismatics.size()) + 1; }
  /// Newton–Euler equations: 3 per moving body.
  std::size_t equations() const { return 3 * movingBodies(); }
  /// The block `key` names, if there is one.
  std::optional<BodyId> findSlider(const SliderKey& key) const;
  /// Whether `body` holds `point`.
  bool holds(BodyId body, PointId point) const;
};

/// The bodies and joints of a mechanism that checkMechanism accepts. Fails (InvalidStructure)
/// if the crank is fixed to the ground, or if unknowns ≠ equations (mobility ≠ 1), naming the
/// count.
Result<BodyModel> bodiesOf(const Mechanism& mechanism);

/// The fixed distance between a link's ends from the definitions (length unit): the crank
/// length, an RRR side, an RRP rod, an RPR slotted link or a constraint.
double linkLength(const Mechanism& mechanism, LinkId link);

/// Unit direction (world frame) along which the block of `joint` slides, at `pose`.
Eigen::Vector2d prismaticDirection(const Mechanism& mechanism, const PrismaticJoint& joint, const Pose& pose);

}  // namespace linkwright::kinematics
