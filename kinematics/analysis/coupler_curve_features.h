#pragma once
// What a coupler curve looks like, found numerically from its samples (coupler_curve.h), as
// an atlas of coupler curves classifies them (Hrones & Nelson 1951; Norton, Design of
// Machinery, §3.6). Every tolerance is a fraction of the curve's size S, the diagonal of its
// bounding box, so the verdicts do not depend on the length unit or the linkage's scale.
//
// Cusp: the point stops while the crank turns, dP/dθ = 0 (it happens where the point lies on
//   the moving centrode: it is then the coupler's instant centre), and so dP/du = 0. Over the
//   pieces about each sample |dP/du|² is followed on the Hermite cubics; a local minimum of it,
//   found by golden section, is a cusp when |dP/du| ≤ kCuspSpeed · S per rad. Reported: the crank angle and the
//   point there, and the least speed found.
// Crunode: the curve crosses itself. Every two pieces that are not neighbours and whose
//   chords' boxes meet (found with a grid of buckets, box_pairs.h) are tested for a crossing
//   of their chords; each crossing is then refined on the two cubics by Newton's
//   method (P_i(s) = P_j(t)), and crossings within kSamePoint · S of one found are the same.
//   The two passages must cross at an angle whose sine is at least kMinCrossingSine (0.6°) on
//   the cubics, or kMinChordCrossingSine (3°) where a piece is a chord (at a toggle): a curve
//   that runs back over itself (a point on the rocker traces an arc there and back, and so does
//   B of a rocking crank) touches itself along a stretch, which is not a crunode. Its two
//   passages' cubics agree to about 1e-8 of S, so where they meet they run parallel to far
//   less than 0.6°, while two chords of one arc cross at up to a piece's turn.
//   Reported: the point and the two crank angles the point passes it at.
// Symmetric (curve_symmetry.h): the curve is its own mirror image about a line, to
//   kSymmetryTolerance · S.
// Straight and circular runs (curve_shape_fits.h): the longest run of samples that lies within
//   kStraightTolerance · S of its least-squares line, counted when its chord is at least
//   kMinStraightLength · S, and the longest within kCircularTolerance · S of its
//   least-squares circle, counted when it is at least kMinArcLength · S long and turns at
//   least kMinArcTurn about its centre (so a nearly straight stretch is not called an arc).
//   Hoeken's straight-line linkage stays within 0.1 % of S of its line over 180° of crank
//   (0.16 % of the line's length, Norton §3.7), so 0.2 % of S finds that whole stretch.

#include "kinematics/analysis/coupler_curve.h"

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace linkwright::kinematics {

inline constexpr double kCuspSpeed = 2e-3;                 ///< of S per rad: |dP/du| at a cusp
inline constexpr double kSamePoint = 1e-6;                 ///< of S: two crossings found are one
inline constexpr double kMinCrossingSine = 0.01;           ///< sin of the least crossing angle on the cubics (0.6°)
inline constexpr double kMinChordCrossingSine = 0.05;      ///< the same where a piece is a chord (3°)
inline constexpr double kSymmetryTolerance = 1e-3;         ///< of S: worst distance of the mirror image
inline constexpr double kStraightTolerance = 2e-3;         ///< of S: worst distance from the line
inline constexpr double kCircularTolerance = 5e-4;         ///< of S: worst distance from the circle
inline constexpr double kMinStraightLength = 0.4;          ///< of S: a straight run's chord
inline constexpr double kMinArcLength = 0.25;              ///< of S: a circular run's length
inline constexpr double kMinArcTurn = 1.0471975511965976;  ///< rad (60°): an arc's least turn

/// A cusp: the point at rest while the crank turns.
struct Cusp {
  double crankAngle = 0.0;                          ///< rad
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  ///< length unit
  double speed = 0.0;                               ///< least |dP/du| found, length unit per rad
  bool operator==(const Cusp&) const = default;
};

/// A crunode: a point the curve passes twice.
struct Crunode {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();  ///< length unit
  std::array<double, 2> crankAngles{};              ///< rad, at each passage, in curve order
  bool operator==(const Crunode&) const = default;
};

/// A mirror line of the curve.
struct SymmetryAxis {
  Eigen::Vector2d point = Eigen::Vector2d::Zero();       ///< a point of the line (the curve's centroid), length unit
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit vector along it, at an angle in (−90°, 90°]
  double deviation = 0.0;  ///< worst distance of the mirrored curve from the curve, length unit
  bool operator==(const SymmetryAxis&) const = default;
};

/// A run of samples close to a line.
struct StraightRun {
  double fromAngle = 0.0;                          ///< rad, the crank angle at the run's first sample
  double toAngle = 0.0;                            ///< rad, at its last
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  ///< length unit: the first sample's point
  Eigen::Vector2d to = Eigen::Vector2d::Zero();    ///< length unit: the last sample's point
  double length = 0.0;                             ///< |to − from|, length unit
  double deviation = 0.0;                          ///< worst distance of a sample from the fitted line, length unit
  std::size_t firstSample = 0;                     ///< the run's first sample's index in the curve
  std::size_t lastSample = 0;                      ///< its last's (below firstSample where it wraps a closed curve)
  bool operator==(const StraightRun&) const = default;
};

/// A run of samples close to a circle.
struct CircularArc {
  double fromAngle = 0.0;                            ///< rad, the crank angle at the run's first sample
  double toAngle = 0.0;                              ///< rad, at its last
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< length unit
  double radius = 0.0;                               ///< length unit
  double turn = 0.0;                                 ///< rad, the angle the run sweeps about the centre
  double deviation = 0.0;                            ///< worst | |P − centre| − radius | over the run, length unit
  std::size_t firstSample = 0;                       ///< the run's first sample's index in the curve
  std::size_t lastSample = 0;                        ///< its last's (below firstSample where it wraps a closed curve)
  bool operator==(const CircularArc&) const = default;
};

/// Everything the classifier found.
struct CurveFeatures {
  double size = 0.0;  ///< S, the bounding box's diagonal, length unit
  std::vector<Cusp> cusps;
  std::vector<Crunode> crunodes;
  std::optional<SymmetryAxis> symmetry;
  std::optional<StraightRun> straight;
  std::optional<CircularArc> circular;
  bool operator==(const CurveFeatures&) const = default;
};

/// What each feature is found to, for a curve of `samples` samples (docs/atlas.md's table):
/// the rules' tolerances (fractions of S, the curve's size) and how closely a feature found is
/// placed. Cusps and crunodes are refined on the Hermite cubics, whose error goes as Δu⁴: the
/// placements are those at 360 samples (checked at 360 and 1440 by
/// tests/kinematics/analysis/classification_accuracy_test.cpp), and (360/samples)⁴ times them
/// below 360. A run's ends are samples: each is placed to one sample step of u.
struct ClassifierTolerances {
  double cuspSpeed = kCuspSpeed;               ///< of S per rad: the most |dP/du| at a cusp
  double cuspAngle = 0.0;                      ///< rad: a cusp's crank angle
  double cuspPoint = 0.0;                      ///< of S: its point
  double crossingAngleDeg = 0.0;               ///< ° : the least crossing angle on the cubics
  double samePoint = kSamePoint;               ///< of S: crossings closer are one
  double crunodePoint = 0.0;                   ///< of S: a crunode's point
  double crunodeAngle = 0.0;                   ///< rad: its crank angles
  double symmetry = kSymmetryTolerance;        ///< of S: the most a mirrored curve misses
  double symmetryAxis = 0.0;                   ///< rad: the mirror line's direction
  double straight = kStraightTolerance;        ///< of S: a straight run's most distance from its line
  double straightLength = kMinStraightLength;  ///< of S: its least chord
  double circular = kCircularTolerance;        ///< of S: a circular run's most distance from its circle
  double arcLength = kMinArcLength;            ///< of S: its least length
  double arcTurnDeg = 0.0;                     ///< °: its least turn
  double runEnd = 0.0;                         ///< rad of u: a run's ends (one sample step)
};

/// The tolerances for a curve of `samples` samples (at least 4).
ClassifierTolerances classifierTolerances(std::size_t samples);

/// The curve's cusps, in curve order.
std::vector<Cusp> findCusps(const CouplerCurve& curve, double size);

/// The curve's crunodes, in the curve order of their first passage.
std::vector<Crunode> findCrunodes(const CouplerCurve& curve, double size);

/// All of the above. A curve of fewer than 4 samples, or of size 0, has none.
CurveFeatures classifyCouplerCurve(const CouplerCurve& curve);

}  // namespace linkwright::kinematics
