#pragma once
// A vertical line across a chart at one x (the crank-angle cursor, a limit position), drawn
// as its own two-point series: moving it replaces those two points and leaves every data
// series alone, so the chart is not re-plotted.

#include <QLineSeries>
#include <QPen>

#include <optional>

class QChart;
class QValueAxis;

namespace linkwright::ui {

class VerticalMarker {
public:
  /// Adds the marker's series to `chart` on the given axes; the chart owns it. Hidden until
  /// setX gives it a position. Never in the legend.
  VerticalMarker(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, const QPen& pen, const QString& objectName);

  /// Moves the line to `x` (plot units), or hides it for nullopt.
  void setX(std::optional<double> x);
  /// The y extent the line spans (the value axis range).
  void setYSpan(double lo, double hi);
  /// Puts the line back on top of the chart's series (after curves were added).
  void raise();

  std::optional<double> x() const { return m_x; }
  QLineSeries* series() const { return m_series; }

private:
  void update();

  QChart* m_chart;
  QLineSeries* m_series;
  std::optional<double> m_x;
  double m_lo = 0.0;
  double m_hi = 1.0;
};

}  // namespace linkwright::ui
