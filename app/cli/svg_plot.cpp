#include "app/cli/svg_plot.h"

#include "kinematics/model/number_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace linkwright::cli {
namespace {

constexpr double kWidth = 720, kHeight = 440, kLeft = 80, kRight = 230, kTop = 40, kBottom = 60;

std::string num(double v) { return kinematics::formatFixed(v, 1); }

std::string escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string logLogPlotSvg(const std::string& title, const std::string& xTitle, const std::string& yTitle,
                          const std::vector<PlotSeries>& series) {
  // A log-log plot shows positive finite points only; the rest would become no coordinate.
  const auto plotted = [](double x, double y) { return x > 0 && y > 0 && std::isfinite(x) && std::isfinite(y); };
  double x0 = 1e300, x1 = 0, y0 = 1e300, y1 = 0;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      if (!plotted(x, y)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  if (x1 <= 0) x0 = y0 = 1, x1 = y1 = 10;
  // Whole decades, so grid lines fall on powers of ten.
  const double lx0 = std::floor(std::log10(x0)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(x1)));
  const double ly0 = std::floor(std::log10(y0)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(y1)));
  const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  const auto px = [&](double x) { return kLeft + (std::log10(x) - lx0) / (lx1 - lx0) * pw; };
  const auto py = [&](double y) { return kTop + (ly1 - std::log10(y)) / (ly1 - ly0) * ph; };
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << num(kLeft) << "\" y=\"24\" font-size=\"15\">" << escaped(title) << "</text>\n";
  for (double d = lx0; d <= lx1; ++d)
    s << "<line x1=\"" << num(px(std::pow(10, d))) << "\" y1=\"" << num(kTop) << "\" x2=\"" << num(px(std::pow(10, d)))
      << "\" y2=\"" << num(kTop + ph) << "\" stroke=\"#ddd\"/>\n<text x=\"" << num(px(std::pow(10, d))) << "\" y=\""
      << num(kTop + ph + 18) << "\" text-anchor=\"middle\">1e" << static_cast<int>(d) << "</text>\n";
  for (double d = ly0; d <= ly1; ++d)
    s << "<line x1=\"" << num(kLeft) << "\" y1=\"" << num(py(std::pow(10, d))) << "\" x2=\"" << num(kLeft + pw)
      << "\" y2=\"" << num(py(std::pow(10, d))) << "\" stroke=\"#ddd\"/>\n<text x=\"" << num(kLeft - 8) << "\" y=\""
      << num(py(std::pow(10, d)) + 4) << "\" text-anchor=\"end\">1e" << static_cast<int>(d) << "</text>\n";
  s << "<rect x=\"" << num(kLeft) << "\" y=\"" << num(kTop) << "\" width=\"" << num(pw) << "\" height=\"" << num(ph)
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  s << "<text x=\"" << num(kLeft + pw / 2) << "\" y=\"" << num(kHeight - 16) << "\" text-anchor=\"middle\">"
    << escaped(xTitle) << "</text>\n<text transform=\"translate(20 " << num(kTop + ph / 2)
    << ") rotate(-90)\" text-anchor=\"middle\">" << escaped(yTitle) << "</text>\n";
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& ser = series[i];
    s << "<polyline fill=\"none\" stroke=\"" << ser.colour << "\" stroke-width=\"2\""
      << (ser.dashed ? " stroke-dasharray=\"6 4\"" : "") << " points=\"";
    for (const auto& [x, y] : ser.points)
      if (plotted(x, y)) s << num(px(x)) << "," << num(py(y)) << " ";
    s << "\"/>\n";
    for (const auto& [x, y] : ser.points)
      if (plotted(x, y))
        s << "<circle cx=\"" << num(px(x)) << "\" cy=\"" << num(py(y)) << "\" r=\"3\" fill=\"" << ser.colour
          << "\"/>\n";
    const double ly = kTop + 14 + 20.0 * static_cast<double>(i);
    s << "<line x1=\"" << num(kLeft + pw + 14) << "\" y1=\"" << num(ly - 4) << "\" x2=\"" << num(kLeft + pw + 40)
      << "\" y2=\"" << num(ly - 4) << "\" stroke=\"" << ser.colour << "\" stroke-width=\"2\""
      << (ser.dashed ? " stroke-dasharray=\"6 4\"" : "") << "/>\n<text x=\"" << num(kLeft + pw + 46) << "\" y=\""
      << num(ly) << "\">" << escaped(ser.label) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace linkwright::cli
