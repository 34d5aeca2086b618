#pragma once
// A coupler curve as the atlas and its classifier (coupler_curve_features.h) read it: the
// solver's samples of a point's path, each with the crank angle it was solved at and the
// point's exact derivative with respect to that angle, dP/dθ (a sweep at ω = 1 rad/s, α = 0
// gives it as the point's velocity). Between two samples the curve is the cubic Hermite
// interpolant of the ends' positions and derivatives,
//   P(s) = h00(s) P0 + h10(s) Δθ P0' + h01(s) P1 + h11(s) Δθ P1',  s ∈ [0, 1], Δθ = θ1 − θ0,
// whose error is O(Δθ⁴): at 1° a step that is 1e-8 of the curve's size, so what is refined
// between samples (a cusp, a crossing) is placed to that accuracy without solving again.
// Where a derivative does not exist (a toggle, where the solver reports a singular pose) or
// two samples share a crank angle (the two assembly branches meeting at a rocking crank's
// limit), the piece is the straight chord.

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

/// A sampled coupler curve. All columns have one entry per sample, in the order the linkage
/// moves through them.
struct CouplerCurve {
  std::vector<double> crankAngle;           ///< rad, the crank's angle the sample was solved at
  std::vector<Eigen::Vector2d> point;       ///< length unit, the mechanism's frame
  std::vector<Eigen::Vector2d> derivative;  ///< dP/dθ, length unit per rad; zero where !rateOk
  std::vector<char> rateOk;                 ///< 1 where dP/dθ exists (not a toggle)
  bool closed = true;                       ///< the last sample joins the first
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
  Eigen::Vector2d m0 = Eigen::Vector2d::Zero();  ///< Δθ · dP/dθ at the start (length unit)
  Eigen::Vector2d m1 = Eigen::Vector2d::Zero();  ///< Δθ · dP/dθ at the end (length unit)
  double theta0 = 0.0;                           ///< rad
  double theta1 = 0.0;                           ///< rad
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
