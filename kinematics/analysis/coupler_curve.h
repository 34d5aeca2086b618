#pragma once
// A coupler curve as the atlas and its classifier (coupler_curve_features.h) read it: the
// solver's samples of a point's path over a parameter u, each with the crank angle it was
// solved at and the point's exact derivative dP/du. For a crank that turns fully u is the crank
// angle θ, and dP/dθ is the point's velocity at ω = 1 rad/s. For a crank that rocks between the
// edges of its range, θ = c − r cos u (c the range's middle, r its half-width): u runs once round
// as the crank goes across on one assembly branch and back on the other, and P(u) is smooth
// through the edges, where dP/dθ is infinite but dP/du = dP/dθ · r sin u is not. Between two
// samples the curve is the cubic Hermite interpolant of the ends' positions and derivatives,
//   P(s) = h00(s) P0 + h10(s) Δu P0' + h01(s) P1 + h11(s) Δu P1',  s ∈ [0, 1], Δu = u1 − u0,
// whose error is O(Δu⁴): at 1° a step that is 1e-8 of the curve's size, so what is refined
// between samples (a cusp, a crossing) is placed to that accuracy without solving again.
// Where a derivative does not exist (a toggle, where the solver reports a singular pose), the
// piece is the straight chord. The crank angle between samples is interpolated linearly in u.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

/// A sampled coupler curve. All columns have one entry per sample, in the order the linkage
/// moves through them.
struct CouplerCurve {
  std::vector<double> parameter;            ///< u, rad, increasing; a closed curve's spans less than 2π
  std::vector<double> crankAngle;           ///< rad, the crank's angle the sample was solved at
  std::vector<Eigen::Vector2d> point;       ///< length unit, the mechanism's frame
  std::vector<Eigen::Vector2d> derivative;  ///< dP/du, length unit per rad; zero where !rateOk
  std::vector<char> rateOk;                 ///< 1 where dP/du exists (not a toggle)
  bool closed = true;                       ///< the last sample joins the first, at u + 2π
  bool operator==(const CouplerCurve&) const = default;

  std::size_t size() const { return point.size(); }
  /// Number of pieces: size() for a closed curve, size() − 1 for an open one.
  std::size_t pieces() const { return size() < 2 ? 0 : (closed ? size() : size() - 1); }
  /// The sample after `i` (wrapping on a closed curve).
  std::size_t next(std::size_t i) const { return i + 1 < size() ? i + 1 : 0; }
};

/// One piece of the curve, from sample i to next(i), as its cubic.
struct CurvePiece {
  Eigen::Vector2d p0 = Eigen::Vector2d::Zero();
  Eigen::Vector2d p1 = Eigen::Vector2d::Zero();
  Eigen::Vector2d m0 = Eigen::Vector2d::Zero();  ///< Δu · dP/du at the start (length unit)
  Eigen::Vector2d m1 = Eigen::Vector2d::Zero();  ///< Δu · dP/du at the end (length unit)
  double du = 0.0;                               ///< Δu, rad
  double theta0 = 0.0;                           ///< crank angle at the start, rad
  double theta1 = 0.0;                           ///< crank angle at the end, rad
  bool cubic = false;                            ///< false: the straight chord

  /// The point at s ∈ [0, 1] (length unit).
  Eigen::Vector2d at(double s) const;
  /// dP/ds at s (length unit).
  Eigen::Vector2d tangent(double s) const;
  /// The crank angle at s (rad), linear in s.
  double angle(double s) const { return theta0 + s * (theta1 - theta0); }
};

/// Piece `i` of `curve` (i < curve.pieces()).
CurvePiece curvePiece(const CouplerCurve& curve, std::size_t i);

/// The diagonal of the curve's bounding box (length unit): the scale every tolerance of the
/// classifier is a fraction of. 0 for an empty curve.
double curveSize(const CouplerCurve& curve);

/// The curve with each piece cut into `parts` equal steps of s (an open polyline; a closed
/// curve's first point is not repeated). What distances to the curve are measured against.
std::vector<Eigen::Vector2d> densified(const CouplerCurve& curve, std::size_t parts);

}  // namespace linkwright::kinematics
