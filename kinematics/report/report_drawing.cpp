// The linkage on the report's first page: the DXF export's plates, holes and ground crosses
// (analysis/link_drawing.h) scaled to fit a box, y up, with a hatched ground symbol under each ground
// pivot, each point's name, and each link's length written along it.

#include "kinematics/report/report_layout.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics::report {
namespace {

// Points from the bottom of a ground pivot's plate to the frame's dimension line.
constexpr double kFrameDrop = 22.0;

// Model (length unit, y up) to page (points, y down).
struct View {
  double scale = 1.0;
  double originX = 0.0, originY = 0.0;  ///< page point of the model's (minX, maxY)
  double minX = 0.0, maxY = 0.0;
  double usedHeight = 0.0;  ///< points, the drawing's and its frame dimension's
  double bottom = 0.0;      ///< page y of the drawing's lowest part
  double x(double mx) const { return originX + (mx - minX) * scale; }
  double y(double my) const { return originY + (maxY - my) * scale; }
};

View fit(const ReportDrawing& d, double left, double top, double width, double height) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  const auto add = [&](const Eigen::Vector2d& p) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  };
  for (const auto& layer : d.parts.layers)
    for (const auto& outline : layer.outlines)
      for (const auto& v : outline) add(v.point);
  for (const auto& [p, name] : d.pointLabels) add(p);
  const double w = d.parts.plateWidth;
  const bool frameDimension =
      std::any_of(d.dimensions.begin(), d.dimensions.end(), [](const Dimension& x) { return x.ground; });
  if (x0 > x1) x0 = y0 = 0.0, x1 = y1 = 1.0;
  const double pad = w / 2.0;
  x0 -= pad, x1 += pad, y0 -= pad, y1 += pad;
  View v;
  // Below the lowest part: the ground symbols, and the frame's dimension line kFrameDrop
  // points under its pivots.
  const double below = frameDimension ? kFrameDrop + 12.0 : 16.0;
  v.scale = std::min(width / (x1 - x0), (height - below) / (y1 - y0));
  v.usedHeight = (y1 - y0) * v.scale + below;
  v.minX = x0;
  v.maxY = y1;
  v.originX = left + (width - (x1 - x0) * v.scale) / 2.0;
  v.originY = top;
  v.bottom = v.y(y0);
  return v;
}

// One edge of an outline: straight, or an arc of bulge b (tan(θ/4), counter-clockwise if > 0).
void edge(cairo_t* cr, const View& v, const kinematics::OutlineVertex& a, const Eigen::Vector2d& b) {
  if (std::abs(a.bulge) < 1e-12) {
    cairo_line_to(cr, v.x(b.x()), v.y(b.y()));
    return;
  }
  const Eigen::Vector2d chord = b - a.point;
  const Eigen::Vector2d normal(-chord.y(), chord.x());
  const Eigen::Vector2d centre = (a.point + b) / 2.0 + normal * ((1.0 - a.bulge * a.bulge) / (4.0 * a.bulge));
  const double radius = (a.point - centre).norm() * v.scale;
  const double from = std::atan2(a.point.y() - centre.y(), a.point.x() - centre.x());
  const double to = std::atan2(b.y() - centre.y(), b.x() - centre.x());
  // y flips on the page, so a counter-clockwise arc in the model runs clockwise there.
  if (a.bulge > 0) cairo_arc_negative(cr, v.x(centre.x()), v.y(centre.y()), radius, -from, -to);
  else cairo_arc(cr, v.x(centre.x()), v.y(centre.y()), radius, -from, -to);
}

void outline(cairo_t* cr, const View& v, const kinematics::Outline& o) {
  if (o.empty()) return;
  cairo_new_sub_path(cr);
  cairo_move_to(cr, v.x(o[0].point.x()), v.y(o[0].point.y()));
  for (std::size_t i = 0; i < o.size(); ++i) edge(cr, v, o[i], o[(i + 1) % o.size()].point);
  cairo_close_path(cr);
}

void parts(cairo_t* cr, const View& v, const kinematics::LinkDrawing& d) {
  cairo_set_line_width(cr, 0.8);
  for (const auto& layer : d.layers) {
    for (const auto& o : layer.outlines) outline(cr, v, o);
    cairo_set_source_rgba(cr, 0.55, 0.70, 0.90, 0.45);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.1, 0.2, 0.4);
    cairo_stroke(cr);
    for (const auto& hole : layer.holes) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, v.x(hole.centre.x()), v.y(hole.centre.y()), hole.diameter / 2.0 * v.scale, 0.0, 2.0 * M_PI);
      cairo_set_source_rgb(cr, 1, 1, 1);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0.1, 0.2, 0.4);
      cairo_stroke(cr);
    }
    for (const auto& line : layer.lines) {
      cairo_move_to(cr, v.x(line.from.x()), v.y(line.from.y()));
      cairo_line_to(cr, v.x(line.to.x()), v.y(line.to.y()));
      cairo_stroke(cr);
    }
  }
}

// A triangle under the pivot on a hatched base: the textbook ground symbol.
void groundSymbol(cairo_t* cr, double x, double y, double size) {
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 0.8);
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x - size * 0.6, y + size);
  cairo_line_to(cr, x + size * 0.6, y + size);
  cairo_close_path(cr);
  cairo_stroke(cr);
  cairo_move_to(cr, x - size, y + size);
  cairo_line_to(cr, x + size, y + size);
  cairo_stroke(cr);
  cairo_set_line_width(cr, 0.5);
  for (double h = -size; h < size; h += size / 3.0) {
    cairo_move_to(cr, x + h + size / 3.0, y + size);
    cairo_line_to(cr, x + h, y + size * 1.35);
  }
  cairo_stroke(cr);
}

// The frame: a dimension line with end ticks under the ground symbols, its length below it.
void groundDimension(cairo_t* cr, const View& v, const Dimension& d, double plateRadius) {
  // Under the pivots' ground symbols, and under every part when the linkage hangs below them.
  const double y = std::max(std::max(v.y(d.from.y()), v.y(d.to.y())) + plateRadius + kFrameDrop, v.bottom + 12.0);
  const double a = v.x(d.from.x()), b = v.x(d.to.x());
  cairo_set_source_rgb(cr, 0.6, 0.1, 0.1);
  cairo_set_line_width(cr, 0.5);
  cairo_move_to(cr, a, y);
  cairo_line_to(cr, b, y);
  for (const double x : {a, b}) {
    cairo_move_to(cr, x, y - 4.0);
    cairo_line_to(cr, x, y + 4.0);
  }
  cairo_stroke(cr);
  setFont(cr, 7.5);
  showText(cr, (a + b) / 2.0 - textWidth(cr, d.text) / 2.0, y + 10.0, d.text);
}

// The length written along the link, upright, on the side away from the linkage's centre.
void dimension(cairo_t* cr, const View& v, const Dimension& d, const Eigen::Vector2d& centre, double plateRadius) {
  const Eigen::Vector2d a(v.x(d.from.x()), v.y(d.from.y()));
  const Eigen::Vector2d b(v.x(d.to.x()), v.y(d.to.y()));
  double angle = std::atan2(b.y() - a.y(), b.x() - a.x());
  if (angle > M_PI / 2.0) angle -= M_PI;
  if (angle < -M_PI / 2.0) angle += M_PI;
  const Eigen::Vector2d mid = (a + b) / 2.0;
  Eigen::Vector2d normal(-std::sin(angle), std::cos(angle));  // below the text's baseline
  const bool outward = normal.dot(mid - centre) > 0.0;
  setFont(cr, 7.5);
  const double w = textWidth(cr, d.text);
  cairo_save(cr);
  cairo_translate(cr, mid.x(), mid.y());
  cairo_rotate(cr, angle);
  cairo_set_source_rgb(cr, 0.6, 0.1, 0.1);
  // Just off the plate's edge, so the text crosses neither the plate nor a point's name.
  showText(cr, -w / 2.0, outward ? plateRadius + 8.0 : -plateRadius - 2.5, d.text);
  cairo_restore(cr);
}

}  // namespace

void drawLinkage(PageCursor& page, const ReportDrawing& d, double height) {
  page.ensure(height);
  cairo_t* cr = page.cr();
  const View v = fit(d, page.left(), page.y(), page.width(), height - 14.0);
  const double used = v.usedHeight + 14.0;
  cairo_save(cr);
  parts(cr, v, d.parts);
  for (const Eigen::Vector2d& g : d.groundPivots)
    groundSymbol(cr, v.x(g.x()), v.y(g.y()) + d.parts.plateWidth / 2.0 * v.scale, 10.0);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& [p, name] : d.pointLabels) centre += Eigen::Vector2d(v.x(p.x()), v.y(p.y()));
  if (!d.pointLabels.empty()) centre /= static_cast<double>(d.pointLabels.size());
  for (const Dimension& dim : d.dimensions) {
    if (dim.ground) groundDimension(cr, v, dim, d.parts.plateWidth / 2.0 * v.scale);
    else dimension(cr, v, dim, centre, d.parts.plateWidth / 2.0 * v.scale);
  }
  setFont(cr, 8.0, true);
  cairo_set_source_rgb(cr, 0, 0, 0);
  for (const auto& [p, name] : d.pointLabels)
    showText(cr, v.x(p.x()) + d.parts.plateWidth / 2.0 * v.scale + 2.0, v.y(p.y()) - 4.0, name);
  setFont(cr, 8.0);
  showText(cr, page.left() + page.width() / 2.0 - textWidth(cr, d.caption) / 2.0, page.y() + used - 2.0, d.caption);
  cairo_restore(cr);
  page.advance(used);
}

}  // namespace linkwright::kinematics::report
