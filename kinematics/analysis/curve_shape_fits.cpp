#include "kinematics/analysis/curve_shape_fits.h"

#include "kinematics/analysis/point_tree.h"
#include "kinematics/analysis/window_fits.h"
#include "kinematics/model/units.h"
#include "kinematics/solve/golden_section.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>

namespace linkwright::kinematics {
namespace {

double distanceToSegment(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double l2 = ab.squaredNorm();
  const double s = l2 > 0.0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + s * ab - x).norm();
}

// The curve for distances: its samples, for finding the nearest (a k-d tree), and its pieces
// cut finely, for measuring against the nearest sample's pieces.
struct MeasuredCurve {
  MeasuredCurve(const CouplerCurve& curve) : samples(&curve.point), tree(curve.point), fine(densified(curve, kParts)) {}
  const std::vector<Eigen::Vector2d>* samples;
  PointTree tree;
  std::vector<Eigen::Vector2d> fine;  // densified(curve, kParts), closed
  static constexpr std::size_t kParts = 8;

  std::size_t nearestSample(const Eigen::Vector2d& x) const { return tree.nearest(x); }
  // The distance to the nearest sample: within half a piece of the distance to the curve.
  double coarseDistance(const Eigen::Vector2d& x) const { return ((*samples)[nearestSample(x)] - x).norm(); }
  // The distance to the fine pieces within two pieces of the nearest sample.
  double distance(const Eigen::Vector2d& x) const {
    const std::size_t n = fine.size(), centre = nearestSample(x) * kParts;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = n + centre - 2 * kParts; k < n + centre + 2 * kParts; ++k)
      best = std::min(best, distanceToSegment(x, fine[k % n], fine[(k + 1) % n]));
    return best;
  }
};

// The centroid of the polyline's arc length.
Eigen::Vector2d arcCentroid(const std::vector<Eigen::Vector2d>& line) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double length = 0.0;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const Eigen::Vector2d& a = line[i];
    const Eigen::Vector2d& b = line[(i + 1) % line.size()];
    const double l = (b - a).norm();
    sum += l * 0.5 * (a + b);
    length += l;
  }
  return length > 0.0 ? Eigen::Vector2d(sum / length) : line.front();
}

Eigen::Vector2d directionAt(double phi) { return {std::cos(phi), std::sin(phi)}; }

// The worst distance of the mirrored `probes` from the curve, coarse (to the nearest sample) or
// fine.
double mismatch(const std::vector<Eigen::Vector2d>& probes, const MeasuredCurve& curve, const Eigen::Vector2d& g,
                double phi, bool fine) {
  const Eigen::Vector2d d = directionAt(phi);
  double worst = 0.0;
  for (const Eigen::Vector2d& x : probes) {
    const Eigen::Vector2d r = x - g;
    const Eigen::Vector2d mirrored = g + 2.0 * r.dot(d) * d - r;
    worst = std::max(worst, fine ? curve.distance(mirrored) : curve.coarseDistance(mirrored));
  }
  return worst;
}

std::vector<Eigen::Vector2d> every(const std::vector<Eigen::Vector2d>& points, std::size_t count) {
  std::vector<Eigen::Vector2d> out;
  const std::size_t step = std::max<std::size_t>(1, points.size() / count);
  for (std::size_t i = 0; i < points.size(); i += step) out.push_back(points[i]);
  return out;
}

// The longest window by `measure` that `fits`, by a sliding window: the window grows while it
// fits, and its start moves on when it does not. `measure(w, beat)` may return 0 for a window
// that cannot beat `beat`.
template <class Fits, class Measure>
std::optional<SampleWindow> longestWindow(const CouplerCurve& curve, const Fits& fits, const Measure& measure) {
  const std::size_t n = curve.size();
  const std::size_t starts = curve.closed ? n : n - 2;
  const std::size_t cap = curve.closed ? n - 1 : 0;  // a closed window holds at most n samples
  std::optional<SampleWindow> best;
  double bestMeasure = 0.0;
  std::size_t last = 0;
  for (std::size_t first = 0; first < starts; ++first) {
    last = std::max(last, first + 2);
    if (!curve.closed && last >= n) break;
    const auto end = curve.closed ? first + cap : n - 1;
    while (last < end && fits(SampleWindow{first, last + 1})) ++last;
    const SampleWindow w{first, last};
    if (!fits(w)) continue;
    // Of runs as long to rounding (a symmetric curve's mirror-image runs), the first.
    const double m = measure(w, bestMeasure * (1.0 + 1e-12));
    if (m > bestMeasure * (1.0 + 1e-12)) {
      bestMeasure = m;
      best = w;
    }
    if (curve.closed && last == end && first == 0) break;  // the whole curve fits
  }
  return best;
}

}  // namespace

double mirrorMismatch(const CouplerCurve& curve, const Eigen::Vector2d& point, const Eigen::Vector2d& direction) {
  const MeasuredCurve measured(curve);
  return mismatch(curve.point, measured, point, std::atan2(direction.y(), direction.x()), true);
}

std::optional<SymmetryAxis> findSymmetry(const CouplerCurve& curve, double size) {
  if (!curve.closed || curve.size() < 8) return std::nullopt;
  const MeasuredCurve measured(curve);
  const Eigen::Vector2d g = arcCentroid(measured.fine);
  const std::vector<Eigen::Vector2d> coarse = every(curve.point, 24), middle = every(curve.point, 48);
  const double step = kPi / 90.0;  // 2°
  std::vector<std::pair<double, double>> scan;
  for (int k = 0; k < 90; ++k) scan.push_back({mismatch(coarse, measured, g, k * step, false), k * step});
  // The local minima of the scan that could be a mirror line, best first. A 2° step moves a
  // mirrored point by up to 3.5 % of the size; the nearest sample adds up to half a piece.
  std::vector<std::pair<double, double>> candidates;
  for (std::size_t k = 0; k < scan.size(); ++k) {
    const double here = scan[k].first;
    if (here <= scan[(k + 1) % scan.size()].first && here <= scan[(k + scan.size() - 1) % scan.size()].first &&
        here <= 0.08 * size)
      candidates.push_back(scan[k]);
  }
  std::sort(candidates.begin(), candidates.end());
  if (candidates.size() > 2) candidates.resize(2);
  std::optional<SymmetryAxis> best;
  for (const auto& [coarseMismatch, phi0] : candidates) {
    const double phi = goldenSectionMinimum([&](double a) { return mismatch(middle, measured, g, a, true); },
                                            phi0 - step, phi0 + step, 0.0, 32)
                           .middle();
    const double deviation = mismatch(curve.point, measured, g, phi, true);
    if (deviation > kSymmetryTolerance * size || (best && deviation >= best->deviation)) continue;
    Eigen::Vector2d d = directionAt(phi);
    if (d.x() < 0.0 || (d.x() == 0.0 && d.y() < 0.0)) d = -d;
    best = SymmetryAxis{g, d, deviation};
  }
  return best;
}

std::optional<StraightRun> findStraightRun(const CouplerCurve& curve, double size) {
  if (curve.size() < 4) return std::nullopt;
  const double tolerance = kStraightTolerance * size;
  const WindowFits windows(curve);
  const auto best = longestWindow(
      curve, [&](SampleWindow w) { return windows.within(w, windows.line(w), tolerance); },
      [&](SampleWindow w, double) { return (windows.at(w.last) - windows.at(w.first)).norm(); });
  if (!best) return std::nullopt;
  const Eigen::Vector2d from = windows.at(best->first), to = windows.at(best->last);
  if ((to - from).norm() < kMinStraightLength * size) return std::nullopt;
  const std::size_t n = curve.size();
  return StraightRun{curve.crankAngle[best->first % n],
                     curve.crankAngle[best->last % n],
                     from,
                     to,
                     (to - from).norm(),
                     windows.deviation(*best, windows.line(*best)),
                     best->first % n,
                     best->last % n};
}

std::optional<CircularArc> findCircularArc(const CouplerCurve& curve, double size) {
  if (curve.size() < 4) return std::nullopt;
  const double tolerance = kCircularTolerance * size;
  const WindowFits windows(curve);
  const auto best = longestWindow(
      curve,
      [&](SampleWindow w) {
        const WindowCircle c = windows.circle(w);
        return c.ok && windows.within(w, c, tolerance);
      },
      [&](SampleWindow w, double beat) {
        const double length = windows.arcLength(w);
        if (length <= beat) return 0.0;
        return windows.turnsAtLeast(w, windows.circle(w), tolerance, kMinArcTurn) ? length : 0.0;
      });
  if (!best) return std::nullopt;
  const WindowCircle c = windows.circle(*best);
  const double turn = windows.turn(*best, c.centre);
  if (windows.arcLength(*best) < kMinArcLength * size || turn < kMinArcTurn) return std::nullopt;
  const std::size_t n = curve.size();
  return CircularArc{curve.crankAngle[best->first % n],
                     curve.crankAngle[best->last % n],
                     c.centre,
                     c.radius,
                     turn,
                     windows.deviation(*best, c),
                     best->first % n,
                     best->last % n};
}

}  // namespace linkwright::kinematics
