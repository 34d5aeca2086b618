#pragma once
// A chart of force quantities against time or crank angle (the driving torque, the joint
// reaction magnitudes): a line per curve, split into segments where the forces were not
// solved, explicit value axes with rounded ranges, and a cursor (VerticalMarker) that moves
// without touching the data. The lines are our own items (curve_item.h); no animations.

#include "ui/plots/angle_unit.h"
#include "ui/plots/axis_range.h"
#include "ui/plots/chart_layout_inputs.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/plots/segmented_line.h"
#include "ui/plots/series_data.h"
#include "ui/plots/vertical_marker.h"

#include <QChartView>
#include <QList>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QValueAxis;

namespace linkwright::ui {

class ForceChartView : public QChartView {
  Q_OBJECT
public:
  /// One line of the chart: its object name ("torque", "joint_B"), legend text, colour.
  using Curve = SegmentedLine::Style;

  /// A chart titled `title`; `fromZero` keeps 0 on the value axis (magnitudes).
  explicit ForceChartView(const QString& title, bool fromZero, QWidget* parent = nullptr);
  ~ForceChartView() override;

  /// Makes one line per curve (keeps the series if the curves are unchanged). The legend is
  /// shown only for more than one curve.
  void setCurves(const std::vector<Curve>& curves);
  /// Replaces the lines with `runs` (one per curve, in order; x on `x`'s axis, y in the value
  /// unit) and resets the axes: x to `x`'s range and title, y around the values. Returns
  /// whether what lays the chart out changed (quantity_chart_view.h). A value axis the data
  /// have left is fitted again with room while they keep changing (refittedRange).
  bool setData(const std::vector<SeriesRuns>& runs, const QString& valueTitle, const PlotXAxis& x,
               DataFlow flow = DataFlow::Settled);
  /// Fits the value axis to the data once they have settled (setData keeps it while it still
  /// serves); returns whether that changed the room its labels take (quantity_chart_view.h).
  bool settleValueRange();
  /// Moves the cursor to `x` (plot units), or hides it. Touches no data series.
  void setCursorX(std::optional<double> x);
  std::optional<double> cursorX() const { return m_cursor->x(); }

  /// The line of curve `index`, or null.
  CurveItem* curveItem(std::size_t index) const;
  /// The samples curve `index` stands for, in order, gaps left out (segmented_line.h).
  QList<QPointF> samples(std::size_t index) const;
  QValueAxis* xAxis() const { return m_xAxis; }
  QValueAxis* yAxis() const { return m_yAxis; }

signals:
  /// The view was resized (and its chart with it).
  void resized();

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  bool m_fromZero;
  QValueAxis* m_xAxis;
  AxisRange m_xRange;  // the last data's x range: its ticks are fitted again to a new width
  QValueAxis* m_yAxis;
  std::vector<SegmentedLine> m_lines;
  std::unique_ptr<VerticalMarker> m_cursor;
  std::vector<double> m_values;       // y values of one update, reused
  ChartLayoutInputs m_layoutInputs;   // as of the last setData
  double m_lo = 0.0, m_hi = 0.0;      // the data's span of the last setData
  std::optional<AxisRange> m_yShown;  // the value axis shown

  AxisRange fittedRange(DataFlow flow) const;  // the value axis fitted to [m_lo, m_hi]
};

}  // namespace linkwright::ui
