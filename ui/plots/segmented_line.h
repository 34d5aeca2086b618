#pragma once
// One curve of a chart drawn as line segments: a curve breaks wherever its samples are missing
// (not assembled, singular), and each run of samples is its own QLineSeries on the chart's two
// axes. Shared by the kinematics and the force charts. Series are updated with replace(), and
// hold only the vertices the plot area can show (screen_simplify.h: every sample within
// kCurveTolerancePx of the drawn line); the samples themselves stay here for the hover
// read-out, so it gives a sample's exact value.

#include "ui/plots/series_data.h"
#include "ui/screen_simplify.h"

#include <QColor>
#include <QList>
#include <QString>

#include <functional>
#include <optional>

class QChart;
class QLineSeries;
class QValueAxis;

namespace linkwright::ui {

class SegmentedLine {
public:
  /// How a segment looks and where it goes: its object name (`key`), legend text and colour.
  struct Style {
    QString key;
    QString name;
    QColor color;
    bool operator==(const Style&) const = default;
  };

  /// Adds the curve's first few (empty, hidden) segments to `chart`, so that a drag into a
  /// gap finds them made. `onNewSegment`, if set, is called for every segment made, these
  /// included (a view connects its hover signal).
  SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style,
                std::function<void(QLineSeries*)> onNewSegment = {});

  /// How far (pixels) a sample may lie from the line drawn through the kept vertices.
  static constexpr double kCurveTolerancePx = 0.2;

  /// Shows `runs`, one segment each (made as needed; spare ones emptied), simplified
  /// for the chart's plot area and axis ranges as they are now: set the axes first. The first
  /// segment stays visible while `shown`, even empty, so the legend names the curve.
  void setRuns(const SeriesRuns& runs, bool shown);
  /// Draws the runs again if the plot area or the axes have changed the scale by more than a
  /// few per cent since they were drawn (a resize, a new axis range).
  void rescale();
  /// The sample of `segment`'s run nearest `x` in x (every sample, not only the vertices drawn).
  std::optional<QPointF> nearestSample(const QLineSeries* segment, qreal x) const;
  /// Takes the segments off the chart and deletes them.
  void removeFromChart();

  /// The samples the curve stands for, run after run (the drawn vertices are some of them).
  QList<QPointF> samples() const;
  const Style& style() const { return m_style; }
  const QList<QLineSeries*>& segments() const { return m_segments; }

private:
  QLineSeries* addSegment();
  ScreenScale currentScale() const;
  void draw();

  QChart* m_chart;
  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  Style m_style;
  std::function<void(QLineSeries*)> m_onNewSegment;
  QList<QLineSeries*> m_segments;
  SeriesRuns m_runs;  // the samples shown, all of them
  bool m_shown = false;
  ScreenScale m_drawnScale;  // the scale m_runs were simplified for
  SimplifyScratch m_scratch;
  QList<QPointF> m_vertices;  // one run's simplified points, reused
};

}  // namespace linkwright::ui
