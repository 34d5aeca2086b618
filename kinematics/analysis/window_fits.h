#pragma once
// A line and a circle fitted to any window of a curve's consecutive samples, and whether every
// sample of the window lies within a tolerance of it, without visiting each sample: what the
// straight and circular runs (curve_shape_fits.h) test as their sliding window grows, which
// refitted and measured the whole window at every step (quadratic in the samples).
//
// The fits come from prefix sums of the samples' moments (about the curve's bounding-box
// centre, in long double): the line is the principal axis of the window's scatter, the circle
// Kåsa's least-squares circle x² + y² + Dx + Ey + F = 0; each is O(1) for any window.
//
// Whether the window is within `tol` of a fit: a segment tree over the samples keeps, for each
// node's range [lo, hi], the chord from sample lo to sample hi and the farthest any of its
// samples lies from that chord (ε). Every sample of a node is then within ε of a point q of the
// chord, so its distance from the line or circle is at most the chord's worst plus ε; the chord's
// worst is at its ends for a line, and for a circle (centre c, radius r) it is the larger of
// |min‖q − c‖ − r| and |max‖q − c‖ − r| over the chord, the first at c's projection and the
// second at an end. A node whose bound is within `tol` is accepted whole; one whose end
// sample is beyond it fails the window; others are split. The answer is that of testing every
// sample, in O(log n) nodes where the curve is smooth on the scale of a node.

#include "kinematics/analysis/coupler_curve.h"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace linkwright::kinematics {

/// A window: samples first … last of the curve (indices past size() wrap on a closed curve;
/// last < first + size()).
struct SampleWindow {
  std::size_t first = 0, last = 0;
  std::size_t count() const { return last - first + 1; }
};

struct WindowLine {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();        ///< length unit
  Eigen::Vector2d direction = Eigen::Vector2d::UnitX();  ///< unit
};

struct WindowCircle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  ///< length unit
  double radius = 0.0;                               ///< length unit
  bool ok = false;                                   ///< false: no circle (a degenerate fit)
};

class WindowFits {
public:
  explicit WindowFits(const CouplerCurve& curve);

  /// The window's total-least-squares line.
  WindowLine line(SampleWindow w) const;
  /// The window's Kåsa circle.
  WindowCircle circle(SampleWindow w) const;
  /// Whether every sample of the window is within `tol` of the line (of the circle).
  bool within(SampleWindow w, const WindowLine& line, double tol) const;
  bool within(SampleWindow w, const WindowCircle& circle, double tol) const;
  /// The worst distance of a sample of the window from the line (the circle): O(window).
  double deviation(SampleWindow w, const WindowLine& line) const;
  double deviation(SampleWindow w, const WindowCircle& circle) const;
  /// The polyline's length through the window's samples.
  double arcLength(SampleWindow w) const;
  /// The angle the window's samples sweep about `centre`, step by step (rad): O(window).
  double turn(SampleWindow w, const Eigen::Vector2d& centre) const;
  /// Whether turn(w, circle.centre) ≥ `least`, for a window within `tol` of `circle`; decided
  /// from bounds where they suffice (a lower bound from every k-th sample, an upper bound from
  /// the arc length and the longest step), else by turn().
  bool turnsAtLeast(SampleWindow w, const WindowCircle& circle, double tol, double least) const;

  const Eigen::Vector2d& at(std::size_t k) const { return m_points[k % m_points.size()]; }

private:
  struct Moments {
    long double n = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0, xr = 0, yr = 0, r = 0;  // r: x² + y²
  };
  Moments sum(SampleWindow w) const;
  void build(std::size_t node, std::size_t lo, std::size_t hi);
  template <class Dist, class ChordWorst>
  bool within(std::size_t node, std::size_t lo, std::size_t hi, std::size_t qlo, std::size_t qhi, const Dist& dist,
              const ChordWorst& chordWorst, double tol) const;
  template <class Dist, class ChordWorst>
  bool windowWithin(SampleWindow w, const Dist& dist, const ChordWorst& chordWorst, double tol) const;

  std::vector<Eigen::Vector2d> m_points;
  Eigen::Vector2d m_origin = Eigen::Vector2d::Zero();
  std::vector<Moments> m_prefix;  // m_prefix[k]: the moments of samples 0 … k − 1, twice round
  std::vector<double> m_length;   // m_length[k]: the polyline's length from sample 0 to k, twice round
  std::vector<double> m_slack;    // ε of each tree node (heap order, root 1)
  double m_longestStep = 0.0;
};

}  // namespace linkwright::kinematics
