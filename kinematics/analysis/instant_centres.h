#pragma once
// Instant centres of velocity of any planar linkage at one solved pose, by Kennedy's circle
// diagram (Norton §6.4, Myszka §6.8, Uicker, Pennock & Shigley §3.15), and the velocity ratio
// and ideal mechanical advantage they give. Bodies are numbered as the texts number them
// (centre_model.h): 1 the frame, then the rigid bodies in the order they are defined, each
// followed by the slider blocks pinned to it, so a four-bar is 1 frame, 2 crank, 3 coupler,
// 4 rocker and a slider-crank 1 frame, 2 crank, 3 rod, 4 slider.
//
//   Primary centres. Two bodies pinned together turn about the pin: Iij is the pin. A block
//   sliding on a body turns with it, so their centre is the point at infinity normal to the
//   slide. kennedy.h finds every other centre: the three centres of any three bodies lie on
//   one line, so Iij is where two lines Iik–Ijk and Iil–Ijl meet. A line through a point at
//   infinity is the line through its other point in that direction; parallel lines meet at
//   infinity (CentreKind::AtInfinity: a direction, never NaN or a huge coordinate); lines that
//   coincide leave the centre Indeterminate (all joints in one line); a centre that no two
//   lines reach stays Unresolved (a linkage with two freedoms, or an indeterminate six-bar such
//   as a Stephenson III whose diagram Kennedy's theorem alone does not close).
//
// Velocity ratio, with input body a (the crank, about the frame pin I1a) and output body b (the
// last body jointed to the frame). Iab belongs to both bodies and has one velocity:
//     ωa ẑ×(Iab − I1a) = ωb ẑ×(Iab − I1b)  ⇒  ωb/ωa = (Iab − I1a)·e / (Iab − I1b)·e,
// e along the frame line I1a→I1b (signed: negative when the output turns against the crank;
// +1 when Iab is at infinity). An output block sliding on the frame, with u its guide's
// direction and n = ẑ×u, has I1b at infinity along n and moves with Iab:
//     v = ωa ẑ×(Iab − I1a) · u = −ωa (Iab − I1a)·n   (v along +u, length unit / s).
// Mechanical advantage, ideal (no friction, no inertia): power in = power out, Ta·ωa = Tb·ωb,
//     turning output   Tb/Ta = ωa/ωb   (dimensionless)
//     sliding output   F/Ta  = ωa/v    (1 / length unit; F along +u)
// Ta is the torque driving the crank, Tb the torque the output delivers to its load, F the
// force a sliding output delivers, all CCW (or along +u) positive; a negative value means the
// output moves against the input's sense. Where the output is at rest (a four-bar's crank and
// coupler in line: Iab = I1a) the advantage is infinite; where the crank cannot drive (Iab on
// the output's pivot; a slider-crank's rod normal to the guide) it is zero.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace linkwright::kinematics {

/// Lines are parallel (and two centres coincide) when the sine of the angle between them is
/// at most this, or a distance is at most this times the linkage's longest joint-to-joint
/// length. Positions carry round-off of about 1e-16 relative, so the intersection of two lines
/// at angle s is good to about 1e-16/s relative: at 1e-9 that is 1e-7, and the point is 1e9
/// lengths away; nearer to parallel it is reported at infinity instead.
inline constexpr double kCentreTolerance = 1e-9;

enum class CentreKind {
  Finite,         ///< a point of the plane: `position`
  AtInfinity,     ///< the point at infinity in `direction` (a pure translation)
  Indeterminate,  ///< every pair of Kennedy's lines to it coincides (all joints in one line)
  Unresolved,     ///< Kennedy's theorem does not reach it: fewer than two lines lead to it
};

/// Where an instant centre lies. Never NaN: unused members are zero.
struct InstantCentre {
  CentreKind kind = CentreKind::Unresolved;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< Finite: length unit, frame of the mechanism
  /// AtInfinity: unit vector. ±d name the same point; we give the one at an angle in
  /// (−90°, 90°] from +x.
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  bool operator==(const InstantCentre&) const = default;
};

enum class CentreRule {
  Pin,      ///< primary: the two bodies share the pin `joint`
  Slide,    ///< primary: one is a block pinned at `joint`, sliding on the other
  Kennedy,  ///< secondary: where the lines Iik–Ijk and Iil–Ijl meet, k and l = `via`
  None,     ///< not found (Unresolved)
};

/// How a centre was found: what a drawing labels and where its Kennedy lines run.
struct CentreOrigin {
  CentreRule rule = CentreRule::None;
  std::string joint;                              ///< Pin, Slide: the pin's point name
  Eigen::Vector2d pin = Eigen::Vector2d::Zero();  ///< Pin, Slide: where that pin is (length unit)
  std::array<std::size_t, 2> via{};               ///< Kennedy: the body numbers k, l
  bool operator==(const CentreOrigin&) const = default;
};

/// The bodies a velocity ratio and a mechanical advantage compare (body numbers; 0 when the
/// linkage has none): the input is a crank turning about a frame pin, the output the last
/// body jointed to the frame, turning about its pin or sliding on a frame guide.
struct RatioBodies {
  std::size_t input = 0;
  std::size_t output = 0;
  bool outputSlides = false;
  bool operator==(const RatioBodies&) const = default;

  bool exists() const { return input != 0 && output != 0; }
};

/// The centres Iij of every pair of bodies i < j at one pose.
struct InstantCentres {
  std::vector<std::string> bodies;  ///< names, bodies[0] being body 1, the frame
  /// Pair (i, j), i < j, at pairIndex(i, j): I12, I13, …, I1n, I23, …, I(n−1)n.
  std::vector<InstantCentre> centres;
  std::vector<CentreOrigin> origins;  ///< how each centre was found, in the same order
  RatioBodies ratio;
  /// A sliding output: its guide's unit direction u (its velocity and force are along +u).
  Eigen::Vector2d outputDirection = Eigen::Vector2d::Zero();
  /// A frame pin (the crank's pivot if there is one): drawings measure "far" from here.
  Eigen::Vector2d anchor = Eigen::Vector2d::Zero();
  /// The longest distance between two joints of one body (length unit): the tolerances' scale.
  double scale = 0.0;
  bool operator==(const InstantCentres&) const = default;

  std::size_t bodyCount() const { return bodies.size(); }
  /// Index of the pair of body numbers i ≠ j (1-based, either order) in `centres`.
  std::size_t pairIndex(std::size_t i, std::size_t j) const;
  const InstantCentre& centre(std::size_t i, std::size_t j) const { return centres[pairIndex(i, j)]; }
  const CentreOrigin& origin(std::size_t i, std::size_t j) const { return origins[pairIndex(i, j)]; }
};

enum class RatioKind {
  Finite,     ///< `value` holds it
  Infinite,   ///< its denominator is zero at this pose (sign not meaningful)
  Undefined,  ///< 0/0, or a centre it needs is indeterminate or unresolved
};

/// A signed ratio that may be infinite; `value` is zero unless Finite.
struct Ratio {
  RatioKind kind = RatioKind::Finite;
  double value = 0.0;
  bool operator==(const Ratio&) const = default;
};

/// What the centres say about input and output motion (see the derivation above).
struct MechanicalAdvantage {
  /// Turning output: ωb/ωa (dimensionless). Sliding output: v/ωa (length unit per rad).
  Ratio velocityRatio;
  /// Turning output: Tb/Ta = ωa/ωb (dimensionless). Sliding output: F/Ta = ωa/v (1 / length unit).
  Ratio advantage;
  bool operator==(const MechanicalAdvantage&) const = default;
};

/// Four-bar centres from its joints (length unit): crank pivot O2, rocker pivot O4, crank tip
/// B, coupler–rocker joint C. Errors: a non-finite coordinate, or joints of one link that
/// coincide (InvalidValue).
Result<InstantCentres> fourBarInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& o4,
                                             const Eigen::Vector2d& b, const Eigen::Vector2d& c);

/// Slider-crank centres from crank pivot O2, crank tip B, slider pin C (length unit) and the
/// guide's direction (any nonzero length; normalised). Errors as for the four-bar, and a zero
/// or non-finite guide direction.
Result<InstantCentres> sliderCrankInstantCentres(const Eigen::Vector2d& o2, const Eigen::Vector2d& b,
                                                 const Eigen::Vector2d& c, const Eigen::Vector2d& guideDirection);

/// The centres of `mechanism` at a pose solved for it (positions are enough): any linkage
/// whose bodies centre_model.h finds. Errors: the checks of checkMechanism and centreModel, or
/// a pose of another mechanism (InvalidStructure).
Result<InstantCentres> instantCentres(const Mechanism& mechanism, const Pose& pose);

/// Velocity ratio and ideal mechanical advantage from the centres: Undefined both when the
/// linkage has no crank input or no output jointed to the frame (ratio.exists() is false).
MechanicalAdvantage mechanicalAdvantage(const InstantCentres& centres);

}  // namespace linkwright::kinematics
