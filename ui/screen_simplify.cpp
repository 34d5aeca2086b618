#include "ui/screen_simplify.h"

#include <cmath>

namespace linkwright::ui {

bool ScreenScale::usable() const {
  return std::isfinite(xPixelsPerUnit) && std::isfinite(yPixelsPerUnit) && xPixelsPerUnit > 0.0 && yPixelsPerUnit > 0.0;
}

void simplifyForScreen(const QList<QPointF>& points, const ScreenScale& scale, double tolerancePx, QList<QPointF>& out,
                       SimplifyScratch& scratch) {
  out.clear();
  const qsizetype n = points.size();
  if (n <= 2 || !scale.usable() || !(tolerancePx > 0.0)) {
    out = points;
    return;
  }
  // In pixels from the first point once, so the search below is a few multiply-adds a point
  // (it is most of a plot's cost at Precise). Differences first: data far from zero keep
  // their digits.
  std::vector<double>& x = scratch.x;
  std::vector<double>& y = scratch.y;
  x.resize(static_cast<std::size_t>(n));
  y.resize(static_cast<std::size_t>(n));
  for (qsizetype i = 0; i < n; ++i) {
    x[static_cast<std::size_t>(i)] = (points[i].x() - points[0].x()) * scale.xPixelsPerUnit;
    y[static_cast<std::size_t>(i)] = (points[i].y() - points[0].y()) * scale.yPixelsPerUnit;
  }
  std::vector<char>& keep = scratch.keep;
  keep.assign(static_cast<std::size_t>(n), 0);
  keep.front() = keep.back() = 1;
  const double tolerance2 = tolerancePx * tolerancePx;
  // Spans still to split, as an explicit stack: no recursion depth to worry about.
  auto& spans = scratch.spans;
  spans.assign(1, {0, n - 1});
  while (!spans.empty()) {
    const auto [first, last] = spans.back();
    spans.pop_back();
    // The point farthest (in pixels) from the segment first–last; distance to `first` when
    // the two coincide.
    const auto f = static_cast<std::size_t>(first), l = static_cast<std::size_t>(last);
    const double bx = x[l] - x[f], by = y[l] - y[f];
    const double length2 = bx * bx + by * by;
    const double inverse = length2 > 0.0 ? 1.0 / length2 : 0.0;
    double worst = -1.0;
    std::size_t at = f;
    for (std::size_t i = f + 1; i < l; ++i) {
      const double px = x[i] - x[f], py = y[i] - y[f];
      double t = (px * bx + py * by) * inverse;
      t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
      const double dx = px - t * bx, dy = py - t * by;
      const double d = dx * dx + dy * dy;
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (worst <= tolerance2) continue;
    keep[at] = 1;
    const auto split = static_cast<qsizetype>(at);
    if (split - first > 1) spans.emplace_back(first, split);
    if (last - split > 1) spans.emplace_back(split, last);
  }
  for (qsizetype i = 0; i < n; ++i)
    if (keep[static_cast<std::size_t>(i)]) out.append(points[i]);
}

}  // namespace linkwright::ui
