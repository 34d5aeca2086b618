#pragma once
// A guide (mechanism.h) at a solved pose: its line in world coordinates, and the constraint it
// puts on a point C sliding along it. The guide is fixed in a body (ground or link k with first
// point A, angle θ, rates ω, α). Derivation, with u the guide's unit direction, n = u⊥ its
// normal, and P the body's material point under C (× the scalar cross, ⊥ a CCW quarter turn):
//
//   Position.     (C − G)×u = 0, G = A + along·e + across·e⊥, u at θ + guide angle.
//   Velocity.     n·vC = n·vP,   vP = vA + ω(C − A)⊥  (C may only slide along u relative to P).
//   Acceleration. n·aC = n·aP + 2ω u·(vC − vP),  aP = aA + α(C − A)⊥ − ω²(C − A):
//                 the Coriolis term 2ω×v_rel, whose normal component is 2ω u·v_rel.
// On the ground ω = α = 0 and vP = aP = 0, so n·vC = n·aC = 0.

#include "kinematics/model/mechanism.h"
#include "kinematics/solve/pose.h"

#include <Eigen/Core>

namespace linkwright::kinematics {

/// A guide's line at a pose, in the mechanism's length unit.
struct GuideLine {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       ///< G, on the line
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< u, unit
};

/// The guide's line given the positions in `pose` (its link's ends must be solved).
GuideLine guideLineAt(const Mechanism& mechanism, const Guide& guide, const Pose& pose);

/// The right-hand side b of n·vC = b for a point C at `c` on the guide (link rates must be in
/// `pose` for a guide on a link).
double guideVelocityRhs(const Mechanism& mechanism, const Guide& guide, const GuideLine& line, const Pose& pose,
                        const Eigen::Vector2d& c);

/// The right-hand side of n·aC = b for C at `c` moving with velocity `vc`.
double guideAccelerationRhs(const Mechanism& mechanism, const Guide& guide, const GuideLine& line, const Pose& pose,
                            const Eigen::Vector2d& c, const Eigen::Vector2d& vc);

/// The normal n = u⊥ of a line.
inline Eigen::Vector2d guideNormal(const GuideLine& line) { return {-line.direction.y(), line.direction.x()}; }

}  // namespace linkwright::kinematics
