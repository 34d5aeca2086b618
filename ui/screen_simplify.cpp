#include "ui/screen_simplify.h"

#include <cmath>

namespace linkwright::ui {
namespace {

// Squared distance in pixels from p to the segment a–b (to a when a == b).
double squaredPixelDistance(QPointF p, QPointF a, QPointF b, const ScreenScale& s) {
  const double px = (p.x() - a.x()) * s.xPixelsPerUnit, py = (p.y() - a.y()) * s.yPixelsPerUnit;
  const double bx = (b.x() - a.x()) * s.xPixelsPerUnit, by = (b.y() - a.y()) * s.yPixelsPerUnit;
  const double length2 = bx * bx + by * by;
  double t = length2 > 0.0 ? (px * bx + py * by) / length2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  const double dx = px - t * bx, dy = py - t * by;
  return dx * dx + dy * dy;
}

}  // namespace

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
    double worst = -1.0;
    qsizetype at = first;
    for (qsizetype i = first + 1; i < last; ++i) {
      const double d = squaredPixelDistance(points[i], points[first], points[last], scale);
      if (d > worst) {
        worst = d;
        at = i;
      }
    }
    if (worst <= tolerance2) continue;
    keep[static_cast<std::size_t>(at)] = 1;
    if (at - first > 1) spans.emplace_back(first, at);
    if (last - at > 1) spans.emplace_back(at, last);
  }
  for (qsizetype i = 0; i < n; ++i)
    if (keep[static_cast<std::size_t>(i)]) out.append(points[i]);
}

}  // namespace linkwright::ui
