#pragma once
// The polar load diagram of one joint: the locus of its reaction force vector (Fx, Fy) in N
// over the cycle, drawn on equal x and y scales (a circle stays round, an angle reads true)
// with axes through the origin, and a dot at the force for the current crank angle. The
// locus breaks where the forces were not solved; it is drawn as the other charts' curves are
// (segmented_line.h).

#include "ui/plots/axis_range.h"
#include "ui/plots/segmented_line.h"
#include "ui/plots/series_data.h"

#include <QChartView>
#include <QColor>
#include <QList>
#include <QPointF>

#include <optional>

class QLineSeries;
class QScatterSeries;
class QValueAxis;

namespace linkwright::ui {

class PolarLoadView : public QChartView {
  Q_OBJECT
public:
  explicit PolarLoadView(QWidget* parent = nullptr);

  /// Replaces the locus (x = Fx, y = Fy, N) and rescales the axes to hold it and the origin,
  /// equal scales. `title` names the joint; `color` is its curve colour.
  void setLocus(const SeriesRuns& locus, const QString& title, const QColor& color);
  /// The force at the current crank angle (N), or none (not solved there). Rescales only if it
  /// lies outside the axes.
  void setCurrent(std::optional<QPointF> force);

  /// The locus' line (a run per stretch of solved samples), or null before setLocus.
  CurveItem* locus() const { return m_locus ? m_locus->item() : nullptr; }
  /// Number of locus points (solved samples) over all runs; the line draws only the vertices
  /// the screen needs of them (ui/screen_simplify.h).
  qsizetype pointCount() const { return m_pointCount; }
  QScatterSeries* currentDot() const { return m_dot; }
  QValueAxis* xAxis() const { return m_xAxis; }
  QValueAxis* yAxis() const { return m_yAxis; }
  /// Newtons per pixel along x and along y (equal once laid out).
  double xScale() const;
  double yScale() const;

private:
  void equalizeScales();

  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  QLineSeries* m_originX;                // the Fx axis line (y = 0)
  QLineSeries* m_originY;                // the Fy axis line (x = 0)
  std::optional<SegmentedLine> m_locus;  // made again for a new colour
  qsizetype m_pointCount = 0;
  QScatterSeries* m_dot;
  // Data extent (N), origin included; the axes show it on equal scales.
  double m_xLo = -1.0, m_xHi = 1.0, m_yLo = -1.0, m_yHi = 1.0;
  bool m_equalizing = false;
};

}  // namespace linkwright::ui
