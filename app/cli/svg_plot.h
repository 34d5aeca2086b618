#pragma once
// A small log-log line plot as SVG text, for `accuracy --svg`: no plotting library is worth a
// dependency for one chart, and SVG opens in every browser and embeds in Markdown.

#include <string>
#include <vector>

namespace linkwright::cli {

struct PlotSeries {
  std::string label;
  std::string colour;  ///< any SVG colour, e.g. "#1f77b4"
  bool dashed = false;
  std::vector<std::pair<double, double>> points;  ///< (x, y); only points with both positive and finite are drawn
};

/// A log-log plot of `series` with decade grid lines, axis titles and a legend.
std::string logLogPlotSvg(const std::string& title, const std::string& xTitle, const std::string& yTitle,
                          const std::vector<PlotSeries>& series);

}  // namespace linkwright::cli
