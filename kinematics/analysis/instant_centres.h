#pragma once
// Instant centres of velocity of the four-bar and the slider-crank at one solved pose, and the
// velocity ratio and ideal mechanical advantage they give (Kennedy's theorem, as in every
// mechanisms text: Norton §6.4, Myszka §6.8). Bodies: 1 frame, 2 crank, 3 coupler (the rod of a
// slider-crank), 4 rocker (the slider).
//
//   Primary centres (the pins):  I12 = O2, I23 = B, I34 = C, and I14 = O4 for the four-bar.
//   The slider translates along the guide, so I14 is the point at infinity normal to it.
//   Kennedy: the three centres of any three bodies lie on one line, so
//     I13 = line(I12, I23) ∩ line(I14, I34),   I24 = line(I12, I14) ∩ line(I23, I34).
// A line through a point at infinity is the line through its other point in that direction.
// Parallel lines meet at infinity: the centre is a direction (CentreKind::AtInfinity), never
// NaN or a huge coordinate. Lines that coincide (all joints in one line) leave the centre
// undetermined (CentreKind::Indeterminate).
//
// Velocity ratio. I24 belongs to link 2 and to link 4 and has one velocity:
//     ω2 ẑ×(I24 − I12) = ω4 ẑ×(I24 − I14)  ⇒  ω4/ω2 = (I24 − I12)·e / (I24 − I14)·e,
// e along the frame line I12→I14 (signed: negative when the rocker turns against the crank;
// +1 when I24 is at infinity). For the slider-crank, with u the guide's direction and
// n = ẑ×u its normal, I14 is at infinity along n and the slider moves with I24:
//     v = ω2 ẑ×(I24 − I12) · u = −ω2 (I24 − I12)·n   (v along +u, length unit / s).
// Mechanical advantage, ideal (no friction, no inertia): power in = power out, T2·ω2 = T4·ω4,
//     four-bar       T4/T2 = ω2/ω4      (dimensionless)
//     slider-crank   F/T2  = ω2/v       (1 / length unit; F along +u)
// T2 is the torque driving the crank, T4 the torque the rocker delivers to its load, F the
// force the slider delivers to its load, all CCW (or along +u) positive; a negative value
// means the output moves against the input's sense. At a toggle where the output is at rest
// (crank and coupler in line: I24 = I12) the advantage is infinite; where the crank cannot
// drive (coupler and rocker in line: I24 = I14; rod normal to the guide) it is zero.

#include "kinematics/model/mechanism.h"
#include "kinematics/model/result.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

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
  Indeterminate,  ///< Kennedy's two lines coincide (all joints in one line): no single point
};

/// Where an instant centre lies. Never NaN: unused members are zero.
struct InstantCentre {
  CentreKind kind = CentreKind::Finite;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< Finite: length unit, frame of the mechanism
  /// AtInfinity: unit vector. ±d name the same point; we give the one at an angle in
  /// (−90°, 90°] from +x.
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  bool operator==(const InstantCentre&) const = default;
};

enum class CentreLinkage { FourBar, SliderCrank };

/// The six centres Iij of bodies i < j (1 frame, 2 crank, 3 coupler/rod, 4 rocker/slider).
struct InstantCentres {
  CentreLinkage linkage = CentreLinkage::FourBar;
  InstantCentre i12, i13, i14, i23, i24, i34;
  /// Slider-crank: the guide's unit direction u (slider velocity and force are along +u).
  /// Four-bar: zero.
  Eigen::Vector2d guideDirection = Eigen::Vector2d::Zero();
  /// The longest of |O2B|, |BC|, |O4C|, |O2O4| (length unit): the scale of the tolerances.
  double scale = 0.0;
  bool operator==(const InstantCentres&) const = default;
};

enum class RatioKind {
  Finite,     ///< `value` holds it
  Infinite,   ///< its denominator is zero at this pose (sign not meaningful)
  Undefined,  ///< 0/0: the centre it needs is indeterminate
};

/// A signed ratio that may be infinite; `value` is zero unless Finite.
struct Ratio {
  RatioKind kind = RatioKind::Finite;
  double value = 0.0;
  bool operator==(const Ratio&) const = default;
};

/// What the centres say about input and output motion (see the derivation above).
struct MechanicalAdvantage {
  /// Four-bar: ω4/ω2 (dimensionless). Slider-crank: v/ω2 (length unit per rad).
  Ratio velocityRatio;
  /// Four-bar: T4/T2 = ω2/ω4 (dimensionless). Slider-crank: F/T2 = ω2/v (1 / length unit).
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

/// The centres of `mechanism` at a pose solved for it (positions are enough). The mechanism
/// must be a four-bar (a crank and one RRR dyad joining its tip to a ground pivot) or a
/// slider-crank (a crank and one RRP dyad on a ground guide), with any points attached to
/// links; else InvalidStructure naming what it has instead.
Result<InstantCentres> instantCentres(const Mechanism& mechanism, const Pose& pose);

/// Velocity ratio and ideal mechanical advantage from the centres.
MechanicalAdvantage mechanicalAdvantage(const InstantCentres& centres);

}  // namespace linkwright::kinematics
