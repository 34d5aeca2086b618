#include "kinematics/analysis/coupler_curve_features.h"

#include "kinematics/analysis/box_pairs.h"
#include "kinematics/analysis/curve_shape_fits.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/golden_section.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

namespace linkwright::kinematics {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// |dP/du|² at u ∈ [−1, 1] across the pieces before and after a sample (u = 0 at the sample).
struct SpeedAround {
  const CurvePiece* before = nullptr;
  const CurvePiece* after = nullptr;

  double angle(double u) const { return u < 0 ? before->angle(1 + u) : after->angle(u); }
  Eigen::Vector2d point(double u) const { return u < 0 ? before->at(1 + u) : after->at(u); }
  double speedSquared(double u) const {
    const CurvePiece& p = u < 0 ? *before : *after;
    return (u < 0 ? p.tangent(1 + u) : p.tangent(u)).squaredNorm() / (p.du * p.du);
  }
};

// A golden-section search of 58 steps shrinks its bracket to 1e-12 of itself.
constexpr int kCuspSearchSteps = 58;

// Where two chords cross, as their parameters; none if they do not (or are parallel).
std::optional<std::pair<double, double>> chordCrossing(const CurvePiece& a, const CurvePiece& b) {
  const Eigen::Vector2d r = a.p1 - a.p0, q = b.p1 - b.p0, d = b.p0 - a.p0;
  const double denom = cross(r, q);
  if (denom == 0.0) return std::nullopt;
  const double s = cross(d, q) / denom, t = cross(d, r) / denom;
  if (s < 0.0 || s > 1.0 || t < 0.0 || t > 1.0) return std::nullopt;
  return std::pair{s, t};
}

// The crossing of two cubic pieces near (s, t), by Newton's method on P_a(s) − P_b(t) = 0.
std::optional<std::pair<double, double>> refinedCrossing(const CurvePiece& a, const CurvePiece& b, double s, double t,
                                                         double size) {
  for (int k = 0; k < 30; ++k) {
    const Eigen::Vector2d f = a.at(s) - b.at(t);
    if (f.norm() <= 1e-13 * size) return std::pair{s, t};
    const Eigen::Vector2d ta = a.tangent(s), tb = b.tangent(t);
    const double det = -cross(ta, tb);
    if (det == 0.0) return std::nullopt;
    // [ta, −tb] (ds, dt) = −f, by Cramer's rule.
    const double ds = cross(-f, -tb) / det, dt = cross(ta, -f) / det;
    s += ds;
    t += dt;
    if (s < -0.1 || s > 1.1 || t < -0.1 || t > 1.1) return std::nullopt;
  }
  return (a.at(s) - b.at(t)).norm() <= 1e-9 * size ? std::optional{std::pair{s, t}} : std::nullopt;
}

}  // namespace

std::vector<Cusp> findCusps(const CouplerCurve& curve, double size) {
  std::vector<Cusp> cusps;
  const std::size_t n = curve.size();
  if (n < 3 || size <= 0.0) return cusps;
  const auto speed = [&](std::size_t i) { return curve.derivative[i].norm(); };
  const double limit = kCuspSpeed * size;
  for (std::size_t i = 0; i < n; ++i) {
    if (!curve.closed && (i == 0 || i + 1 == n)) continue;
    const std::size_t prev = i == 0 ? n - 1 : i - 1, next = curve.next(i);
    if (!curve.rateOk[i] || !curve.rateOk[prev] || !curve.rateOk[next]) continue;
    if (!(speed(i) < speed(prev) && speed(i) <= speed(next))) continue;
    const CurvePiece before = curvePiece(curve, prev), after = curvePiece(curve, i);
    if (!before.cubic || !after.cubic) continue;
    const SpeedAround around{&before, &after};
    const double u =
        goldenSectionMinimum([&](double v) { return around.speedSquared(v); }, -1.0, 1.0, 0.0, kCuspSearchSteps)
            .middle();
    const double least = std::sqrt(around.speedSquared(u));
    if (least > limit) continue;
    cusps.push_back({around.angle(u), around.point(u), least});
  }
  return cusps;
}

std::vector<Crunode> findCrunodes(const CouplerCurve& curve, double size) {
  std::vector<Crunode> found;
  const std::size_t n = curve.pieces();
  if (n < 4 || size <= 0.0) return found;
  std::vector<CurvePiece> pieces;
  std::vector<Eigen::AlignedBox2d> boxes;
  pieces.reserve(n);
  boxes.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    pieces.push_back(curvePiece(curve, i));
    Eigen::AlignedBox2d box(pieces.back().p0);
    box.extend(pieces.back().p1);
    boxes.push_back(box);
  }
  // Only pieces whose boxes meet can cross (box_pairs.h: O(n log n)), in the order of i then j.
  for (const auto& [i, j] : intersectingBoxPairs(boxes)) {
    if (j < i + 2) continue;                             // neighbours
    if (curve.closed && i == 0 && j == n - 1) continue;  // neighbours across the closing piece
    const auto chord = chordCrossing(pieces[i], pieces[j]);
    if (!chord) continue;
    auto [s, t] = *chord;
    bool refined = false;
    if (pieces[i].cubic && pieces[j].cubic)
      if (const auto on = refinedCrossing(pieces[i], pieces[j], s, t, size)) {
        std::tie(s, t) = *on;
        refined = true;
      }
    // A curve that runs back over itself (a point on the rocker, whose path is an arc
    // traced there and back) touches itself along a stretch: not a crossing.
    const Eigen::Vector2d ti = pieces[i].tangent(s).normalized(), tj = pieces[j].tangent(t).normalized();
    if (std::abs(cross(ti, tj)) < (refined ? kMinCrossingSine : kMinChordCrossingSine)) continue;
    const Eigen::Vector2d point = pieces[i].at(s);
    const bool seen = std::any_of(found.begin(), found.end(),
                                  [&](const Crunode& c) { return (c.point - point).norm() <= kSamePoint * size; });
    if (!seen) found.push_back({point, {pieces[i].angle(s), pieces[j].angle(t)}});
  }
  return found;
}

ClassifierTolerances classifierTolerances(std::size_t samples) {
  const double n = static_cast<double>(std::max<std::size_t>(samples, 4));
  const double coarse = n < 360.0 ? std::pow(360.0 / n, 4) : 1.0;
  ClassifierTolerances t;
  t.cuspAngle = 1e-6 * coarse;
  t.cuspPoint = 1e-6 * coarse;
  t.crossingAngleDeg = std::asin(kMinCrossingSine) * 180.0 / kPi;
  t.crunodePoint = 1e-7 * coarse;
  t.crunodeAngle = 1e-6 * coarse;
  t.symmetryAxis = 1e-3 * coarse;
  t.arcTurnDeg = kMinArcTurn * 180.0 / kPi;
  t.runEnd = 2.0 * kPi / n;
  return t;
}

CurveFeatures classifyCouplerCurve(const CouplerCurve& curve) {
  CurveFeatures features;
  features.size = curveSize(curve);
  if (curve.size() < 4 || !(features.size > 0.0)) return features;
  features.cusps = findCusps(curve, features.size);
  features.crunodes = findCrunodes(curve, features.size);
  features.symmetry = findSymmetry(curve, features.size);
  features.straight = findStraightRun(curve, features.size);
  features.circular = findCircularArc(curve, features.size);
  return features;
}

}  // namespace linkwright::kinematics
