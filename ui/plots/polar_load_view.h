#pragma once
// The polar load diagram of one joint: the locus of its reaction force vector (Fx, Fy) in N
// over the cycle, drawn on equal x and y scales (a circle stays round, an angle reads true)
// with axes through the origin, and a dot at the force for the current crank angle. The
// locus breaks where the forces were not solved. Series are updated with replace().

#include "ui/plots/axis_range.h"
#include "ui/plots/series_data.h"
#include "ui/screen_simplify.h"

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

  /// The locus' segments (one per run of solved samples).
  QList<QLineSeries*> segments() const { return m_segments; }
  /// Number of locus points (solved samples) over all segments; the segments draw only the
  /// vertices the screen needs of them (ui/screen_simplify.h).
  qsizetype pointCount() const { return m_locus.pointCount(); }
  QScatterSeries* currentDot() const { return m_dot; }
  QValueAxis* xAxis() const { return m_xAxis; }
  QValueAxis* yAxis() const { return m_yAxis; }
  /// Newtons per pixel along x and along y (equal once laid out).
  double xScale() const;
  double yScale() const;

private:
  QLineSeries* addSegment();
  void equalizeScales();
  // The locus' segments, simplified for the axes' current scale.
  void drawLocus();

  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  QLineSeries* m_originX;  // the Fx axis line (y = 0)
  QLineSeries* m_originY;  // the Fy axis line (x = 0)
  QList<QLineSeries*> m_segments;
  QScatterSeries* m_dot;
  QColor m_color;
  // Data extent (N), origin included; the axes show it on equal scales.
  double m_xLo = -1.0, m_xHi = 1.0, m_yLo = -1.0, m_yHi = 1.0;
  bool m_equalizing = false;
  SeriesRuns m_locus;              // every solved sample
  double m_drawnPixelsPerN = 0.0;  // the scale m_locus was drawn for
  SimplifyScratch m_scratch;
  QList<QPointF> m_vertices;  // one run's simplified points, reused
};

}  // namespace linkwright::ui
