#pragma once
// A polyline with the vertices removed that a screen cannot show: Ramer–Douglas–Peucker in
// pixel coordinates. Every input point lies within `tolerancePx` of the result, which keeps
// the first and last points and only input points, so peaks and kinks stay where they are
// to a fraction of a pixel. A smooth curve of a few hundred samples drawn across a few
// hundred pixels keeps about a tenth of them, and the cost of drawing a wide antialiased line
// (and Qt Charts' hover shape, a stroke of the whole path) follows the vertex count. Used by
// the plots' curves and the canvas's paths.
//
// Min/max per pixel column, the usual decimation, removes nothing at one or two samples a
// column (the plots' Normal sampling), so it is not used: this one gains at every quality.

#include <QList>
#include <QPointF>

#include <utility>
#include <vector>

namespace linkwright::ui {

/// How many pixels one unit of data spans on each axis (both > 0 and finite to simplify).
struct ScreenScale {
  double xPixelsPerUnit = 0.0;
  double yPixelsPerUnit = 0.0;
  bool usable() const;
};

/// Working memory of simplifyForScreen, kept between calls so that a drag allocates nothing.
struct SimplifyScratch {
  std::vector<double> x, y;  // the points in pixels
  std::vector<char> keep;
  std::vector<std::pair<qsizetype, qsizetype>> spans;
};

/// Writes into `out` the points of `points` that a drawing at `scale` needs to stay within
/// `tolerancePx` of every point of `points` (all of them if the scale is not usable).
void simplifyForScreen(const QList<QPointF>& points, const ScreenScale& scale, double tolerancePx, QList<QPointF>& out,
                       SimplifyScratch& scratch);

}  // namespace linkwright::ui
