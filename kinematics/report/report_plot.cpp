// The report's line plots, drawn as vectors: linear axes on "nice" ticks (1, 2 or 5 × 10ⁿ),
// grid lines, one coloured curve per quantity (the palette of the CLI's SVG plots) and a
// legend to the right of the plot area. Curves are broken where the quantity is undefined.

#include "kinematics/model/number_text.h"
#include "kinematics/report/report_layout.h"

#include <algorithm>
#include <cmath>

namespace linkwright::kinematics::report {
namespace {

struct Range {
  double from = 0.0;
  double to = 1.0;
};

struct Rgb {
  double r, g, b;
};

constexpr Rgb kPalette[] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16}, {0.17, 0.63, 0.17}, {1.00, 0.50, 0.05},
                            {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29}, {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50}};

double niceStep(double span, int wanted) {
  const double raw = span / wanted;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

// The data's range widened to whole ticks; a flat curve gets a unit span around its value.
std::pair<Range, double> axisRange(double lo, double hi, int wanted) {
  if (!(hi > lo)) lo -= 1.0, hi += 1.0;
  const double step = niceStep(hi - lo, wanted);
  return {{std::floor(lo / step + 1e-9) * step, std::ceil(hi / step - 1e-9) * step}, step};
}

std::string tickText(double v, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return kinematics::formatFixed(std::abs(v) < step * 1e-9 ? 0.0 : v, decimals);
}

void dataBounds(const ReportPlot& plot, Range& x, Range& y) {
  x = {1e300, -1e300};
  y = {1e300, -1e300};
  for (const PlotCurve& c : plot.curves)
    for (const auto& segment : c.segments)
      for (const Eigen::Vector2d& p : segment) {
        x = {std::min(x.from, p.x()), std::max(x.to, p.x())};
        y = {std::min(y.from, p.y()), std::max(y.to, p.y())};
      }
  if (x.from > x.to) x = {0.0, 1.0};
  if (y.from > y.to) y = {0.0, 1.0};
}

struct Frame {
  double left, top, width, height;
  Range x, y;
  double px(double v) const { return left + (v - x.from) / (x.to - x.from) * width; }
  double py(double v) const { return top + height - (v - y.from) / (y.to - y.from) * height; }
};

void axes(cairo_t* cr, const Frame& f, double xStep, double yStep) {
  setFont(cr, 7.0);
  cairo_set_line_width(cr, 0.4);
  for (double v = f.x.from; v <= f.x.to + xStep * 1e-6; v += xStep) {
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, f.px(v), f.top);
    cairo_line_to(cr, f.px(v), f.top + f.height);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::string t = tickText(v, xStep);
    showText(cr, f.px(v) - textWidth(cr, t) / 2.0, f.top + f.height + 10.0, t);
  }
  for (double v = f.y.from; v <= f.y.to + yStep * 1e-6; v += yStep) {
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_move_to(cr, f.left, f.py(v));
    cairo_line_to(cr, f.left + f.width, f.py(v));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const std::string t = tickText(v, yStep);
    showText(cr, f.left - textWidth(cr, t) - 4.0, f.py(v) + 2.5, t);
  }
  cairo_set_line_width(cr, 0.8);
  cairo_rectangle(cr, f.left, f.top, f.width, f.height);
  cairo_stroke(cr);
}

void curves(cairo_t* cr, const Frame& f, const ReportPlot& plot) {
  cairo_save(cr);
  cairo_rectangle(cr, f.left, f.top, f.width, f.height);
  cairo_clip(cr);
  cairo_set_line_width(cr, 1.2);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (std::size_t i = 0; i < plot.curves.size(); ++i) {
    const Rgb& c = kPalette[i % std::size(kPalette)];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    for (const auto& segment : plot.curves[i].segments) {
      for (std::size_t k = 0; k < segment.size(); ++k)
        (k ? cairo_line_to : cairo_move_to)(cr, f.px(segment[k].x()), f.py(segment[k].y()));
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
}

void legend(cairo_t* cr, double x, double y, const ReportPlot& plot) {
  setFont(cr, 7.5);
  for (std::size_t i = 0; i < plot.curves.size(); ++i) {
    const Rgb& c = kPalette[i % std::size(kPalette)];
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_line_width(cr, 2.0);
    cairo_move_to(cr, x, y + 12.0 * static_cast<double>(i) - 2.5);
    cairo_line_to(cr, x + 14.0, y + 12.0 * static_cast<double>(i) - 2.5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    showText(cr, x + 18.0, y + 12.0 * static_cast<double>(i), plot.curves[i].label);
  }
}

}  // namespace

void drawPlot(PageCursor& page, const ReportPlot& plot, double height) {
  page.ensure(height);
  cairo_t* cr = page.cr();
  constexpr double kLegendWidth = 100.0;
  Range xData, yData;
  dataBounds(plot, xData, yData);
  auto [x, xStep] = axisRange(xData.from, xData.to, 8);
  // Degrees tick in the steps a protractor has: 15°, 30°, 45°, 90°.
  if (plot.xTitle.ends_with("(deg)")) {
    const double span = xData.to - xData.from;
    for (const double step : {15.0, 30.0, 45.0, 90.0, 180.0})
      if (span / step <= 9.0 || step == 180.0) {
        xStep = step;
        break;
      }
    x = {std::floor(xData.from / xStep + 1e-9) * xStep, std::ceil(xData.to / xStep - 1e-9) * xStep};
  }
  const auto [y, yStep] = axisRange(yData.from, yData.to, 6);
  const Frame f{page.left() + 46.0, page.y() + 20.0, page.width() - 46.0 - kLegendWidth, height - 52.0, x, y};
  setFont(cr, 10.0, true);
  showText(cr, page.left(), page.y() + 11.0, plot.title + " (" + plot.yTitle + ")");
  axes(cr, f, xStep, yStep);
  curves(cr, f, plot);
  setFont(cr, 8.0);
  showText(cr, f.left + f.width / 2.0 - textWidth(cr, plot.xTitle) / 2.0, f.top + f.height + 24.0, plot.xTitle);
  legend(cr, f.left + f.width + 10.0, f.top + 8.0, plot);
  page.advance(height);
}

}  // namespace linkwright::kinematics::report
