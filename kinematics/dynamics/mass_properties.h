#pragma once
// What inverse dynamics needs besides the geometry: the mass, centre of mass and moment of
// inertia of each link and slider block, and the loads (gravity, torques on links, forces at
// points). Plain values named by link and point names, so documents and the GUI carry them
// unchanged; checkDynamics validates them against a mechanism. Links and blocks not listed
// are massless. Seed 004 (Funsho, four-bar dynamics) gives the example's values.
//
// Units: kg, kg·m², N, N·m, m/s² (SI), except positions on a link, which are in the
// mechanism's length unit like every other position (converted with metresPerLengthUnit).

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// Standard gravity, m/s² (the magnitude used when gravity is switched on without a vector).
inline constexpr double kStandardGravity = 9.80665;

/// A position on a link in the link's frame (as for an AttachedPoint): `along` the direction
/// from its first point to its second, `across` 90° CCW from it, from its first point, length unit.
struct LinkFramePoint {
  double along = 0.0;
  double across = 0.0;
  bool operator==(const LinkFramePoint&) const = default;
};

/// Mass properties of one link (the body the link lies on carries them).
struct LinkMass {
  std::string link;                      ///< the link's name
  double mass = 0.0;                     ///< kg, finite, ≥ 0
  std::optional<LinkFramePoint> centre;  ///< centre of mass; default the link's midpoint
  std::optional<double>
      inertia;  ///< kg·m² about the centre of mass, ≥ 0; default m·L²/12 (uniform slender bar, L in m)
  bool operator==(const LinkMass&) const = default;
};

/// Where `mass`'s centre of mass is (length unit, world frame) on a link from `first` to `second`
/// (its joints' positions): its centre in the link's frame, or the midpoint by default.
Eigen::Vector2d massCentreAt(const LinkMass& mass, const Eigen::Vector2d& first, const Eigen::Vector2d& second);

/// Mass of one slider block, whose centre of mass is its pin.
struct SliderMass {
  std::string point;     ///< the slider's defining point (an rrp, rpr or prp point), by name
  int guide = 0;         ///< for a prp point: 0 the block on the first guide, 1 on the second
  double mass = 0.0;     ///< kg, finite, ≥ 0
  double inertia = 0.0;  ///< kg·m² about the pin, finite, ≥ 0 (it turns with its guide)
  bool operator==(const SliderMass&) const = default;
};

/// A torque on a link's body from outside the linkage (its reaction is not on the frame).
struct LinkTorque {
  std::string link;     ///< by name
  double torque = 0.0;  ///< N·m, CCW positive, the same at every sample
  bool operator==(const LinkTorque&) const = default;
};

/// A force from outside the linkage, fixed in direction and size (a gas force, a payload).
/// On a link: at the named point, which must lie on that link's body. On a slider: `link` is
/// empty and `point` names the slider's defining point (as SliderMass); it acts at the pin.
struct PointForce {
  std::string link;   ///< the link it acts on, or empty for a slider block
  std::string point;  ///< the point of application (a link), or the slider's defining point
  int guide = 0;      ///< for a prp slider: which block (0, 1)
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  ///< N, world frame
  bool operator==(const PointForce&) const = default;
};

/// Largest accepted spring stiffness, N/m.
inline constexpr double kMaxStiffness = 1e15;

/// One end of a spring: a point on a link's body, or a point fixed to the frame (a ground point;
/// `link` empty).
struct SpringEnd {
  std::string link;   ///< the link whose body holds it, or empty for the frame
  std::string point;  ///< by name
  bool operator==(const SpringEnd&) const = default;
};

/// A linear spring between two points. Its tension k (L − L0) + preload (N; negative pushes)
/// acts along the line between its ends, pulling each toward the other; L is the distance
/// between them at the pose. Its force enters the inverse dynamics as a load that changes with
/// the pose; where an end is on the frame, the frame feels it (the shaking force counts it).
struct Spring {
  std::string name;
  SpringEnd first;
  SpringEnd second;
  double stiffness = 0.0;   ///< k, N/m, in [0, 1e15]
  double freeLength = 0.0;  ///< L0, length unit, in [0, 1e9]
  double preload = 0.0;     ///< N, the tension at the free length
  bool operator==(const Spring&) const = default;
};

/// External loads. Gravity is off unless given.
struct Loads {
  /// Gravitational acceleration, m/s², world frame (e.g. (0, −kStandardGravity)); off if empty.
  std::optional<Eigen::Vector2d> gravity;
  std::vector<LinkTorque> torques;
  std::vector<PointForce> forces;
  std::vector<Spring> springs;
  bool operator==(const Loads&) const = default;
};

/// Everything about a linkage's masses and loads.
struct LinkageDynamics {
  std::vector<LinkMass> links;
  std::vector<SliderMass> sliders;
  Loads loads;
  bool operator==(const LinkageDynamics&) const = default;

  /// True when nothing is given: no masses and no loads (forces are then all zero).
  bool empty() const;
};

/// The default gravity vector when it is switched on: (0, −9.80665) m/s².
inline Eigen::Vector2d standardGravity() { return {0.0, -kStandardGravity}; }

/// The first problem, naming the field ("links[1].mass must be finite and ≥ 0 (got -1)",
/// "links[0].link names no link of this mechanism (got \"bar\")", "loads.forces[0].point ..."),
/// or nullopt. The mechanism must pass checkMechanism. The length unit is checked when
/// forces are solved (inverse_dynamics.h), not here.
std::optional<Error> checkDynamics(const Mechanism& mechanism, const LinkageDynamics& dynamics);

}  // namespace linkwright::kinematics
