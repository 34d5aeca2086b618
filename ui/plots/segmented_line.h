#pragma once
// One curve of a chart drawn as line segments: a curve breaks wherever its samples are missing
// (not assembled, singular), and each run of samples is its own QLineSeries on the chart's two
// axes. Shared by the kinematics and the force charts. Series are updated with replace().

#include "ui/plots/series_data.h"

#include <QColor>
#include <QList>
#include <QString>

#include <functional>

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

  /// Adds the curve's first (empty, hidden) segment to `chart`. `onNewSegment`, if set, is
  /// called for every segment made, the first included (a view connects its hover signal).
  SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style,
                std::function<void(QLineSeries*)> onNewSegment = {});

  /// Shows `runs`, one segment each (made as needed; spare ones emptied and hidden). The first
  /// segment stays visible while `shown`, even empty, so the legend names the curve.
  void setRuns(const SeriesRuns& runs, bool shown);
  /// Takes the segments off the chart and deletes them.
  void removeFromChart();

  const Style& style() const { return m_style; }
  const QList<QLineSeries*>& segments() const { return m_segments; }

private:
  QLineSeries* addSegment();

  QChart* m_chart;
  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  Style m_style;
  std::function<void(QLineSeries*)> m_onNewSegment;
  QList<QLineSeries*> m_segments;
};

}  // namespace linkwright::ui
