#pragma once
// The symmetry and the straight and circular runs of a coupler curve (the rules and
// tolerances are coupler_curve_features.h's).
//
// Symmetry. A mirror line of a closed curve passes through its centroid G (the centroid of its
// arc length, which a reflection keeps), so only its direction φ is searched: the mismatch
// m(φ) = the worst distance from a mirrored sample to the curve (measured against the curve cut
// finely on its cubics, near the mirrored sample's nearest sample, found in a k-d tree:
// point_tree.h). m is scanned every 2° over half a turn on a subset of the samples, the best
// directions are refined by golden section, and the best is checked on every sample: O(n log n).
// An open curve is not tested.
//
// Runs. A run is a stretch of consecutive samples (wrapping on a closed curve). Its line is the
// total-least-squares line (the principal axis of the samples' scatter), its circle the
// algebraic least-squares circle x² + y² + Dx + Ey + F = 0 (Kåsa), both from prefix sums; the
// run's deviation is its worst sample's distance. The longest run within the tolerance is
// found by a sliding window: the window grows while it fits, and its start moves on when it
// does not. Each window is fitted in O(1) and tested against the tolerance in O(log n)
// (window_fits.h), so the search is O(n log n), not O(n²).

#include "kinematics/analysis/coupler_curve_features.h"

#include <optional>

namespace linkwright::kinematics {

/// The curve's mirror line, if its mismatch is within kSymmetryTolerance · size.
std::optional<SymmetryAxis> findSymmetry(const CouplerCurve& curve, double size);

/// The worst distance of the curve mirrored about the line through `point` along `direction`
/// (unit) from the curve itself (length unit).
double mirrorMismatch(const CouplerCurve& curve, const Eigen::Vector2d& point, const Eigen::Vector2d& direction);

/// The longest straight run (coupler_curve_features.h's rule), if there is one.
std::optional<StraightRun> findStraightRun(const CouplerCurve& curve, double size);

/// The longest circular arc (coupler_curve_features.h's rule), if there is one.
std::optional<CircularArc> findCircularArc(const CouplerCurve& curve, double size);

}  // namespace linkwright::kinematics
