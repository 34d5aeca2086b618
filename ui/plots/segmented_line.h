#pragma once
// One curve of a chart, broken wherever its samples are missing (not assembled, singular) into
// runs that no line joins. Shared by the kinematics and the force charts. The runs are drawn
// by one CurveItem (curve_item.h) and hold only the vertices the plot area can show
// (screen_simplify.h: every sample within kCurveTolerancePx of the drawn line); the samples
// themselves stay here for the hover read-out, so it gives a sample's exact value. An empty
// series of the chart names the curve in the legend.

#include "ui/plots/curve_item.h"
#include "ui/plots/series_data.h"
#include "ui/screen_simplify.h"

#include <QColor>
#include <QList>
#include <QString>

#include <optional>

class QChart;
class QLineSeries;
class QValueAxis;

namespace linkwright::ui {

class SegmentedLine {
public:
  /// How the curve looks and where it goes: its object name (`key`), legend text and colour.
  struct Style {
    QString key;
    QString name;
    QColor color;
    Qt::PenStyle dash = Qt::SolidLine;  ///< dashed for a curve shown for comparison
    bool operator==(const Style&) const = default;
  };

  /// Adds the curve (hidden, empty) and its legend entry to `chart`.
  SegmentedLine(QChart* chart, QValueAxis* xAxis, QValueAxis* yAxis, Style style);

  /// How far (pixels) a sample may lie from the line drawn through the kept vertices.
  static constexpr double kCurveTolerancePx = 0.2;

  /// Shows `runs`, simplified for the chart's plot area and axis ranges as they are now: set
  /// the axes first. The legend names the curve while `shown`, even with no runs.
  void setRuns(const SeriesRuns& runs, bool shown);
  /// Draws the runs again if the plot area or the axes have changed the scale by more than a
  /// few per cent since they were drawn (a resize, a new axis range).
  void rescale();
  /// Names the curve's legend entry (Style::name until then).
  void setLegendName(const QString& name);
  /// The series whose legend marker stands for the curve.
  const QLineSeries* legendSeries() const { return m_legendEntry; }
  /// The sample of run `run` nearest `x` in x (every sample, not only the vertices drawn).
  std::optional<QPointF> nearestSample(qsizetype run, qreal x) const;
  /// Takes the curve and its legend entry off the chart and deletes them.
  void removeFromChart();

  /// The samples the curve stands for, run after run (the drawn vertices are some of them).
  QList<QPointF> samples() const;
  const Style& style() const { return m_style; }
  /// The line drawn (its hovered signal tells which run the mouse is on).
  CurveItem* item() const { return m_item; }

private:
  ScreenScale currentScale() const;
  void draw();

  QChart* m_chart;
  QValueAxis* m_xAxis;
  QValueAxis* m_yAxis;
  Style m_style;
  QLineSeries* m_legendEntry;  // owned by the chart; never given points
  CurveItem* m_item;           // owned by the chart
  SeriesRuns m_runs;           // the samples shown, all of them
  bool m_shown = false;
  ScreenScale m_drawnScale;  // the scale m_runs were simplified for
  SimplifyScratch m_scratch;
};

}  // namespace linkwright::ui
