#pragma once
// One chart of one kind of quantity (angles, ω, α, slider positions, velocities or
// accelerations) against time or crank angle (plot_x_axis.h): a line per selected quantity,
// split into segments where the sweep has no value, explicit value axes with rounded ranges,
// a cursor that moves without touching the data, and another tool's rows as markers over the
// lines (compare_overlay.h).

#include "ui/plots/axis_range.h"
#include "ui/plots/chart_layout_inputs.h"
#include "ui/plots/compare_overlay.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/plot_x_axis.h"
#include "ui/plots/segmented_line.h"
#include "ui/plots/series_data.h"
#include "ui/plots/vertical_marker.h"

#include "kinematics/solve/sweep.h"

#include <QChartView>
#include <QList>

#include <memory>
#include <vector>

class QScatterSeries;
class QValueAxis;

namespace linkwright::ui {

class QuantityChartView : public QChartView {
  Q_OBJECT
public:
  /// A chart titled `title` for the quantities of `kind`; it has no curves until setCurves.
  QuantityChartView(QuantityKind kind, const QString& title, QWidget* parent = nullptr);

  /// Makes one curve for each of `curves` of this chart's kind (the others are ignored),
  /// hidden until setData. Keeps the series when the curves are the same as before.
  void setCurves(const std::vector<PlotCurve>& curves);
  ~QuantityChartView() override;

  QuantityKind kind() const { return m_kind; }
  QValueAxis* xAxis() const { return m_xAxis; }
  QValueAxis* yAxis() const { return m_yAxis; }
  const AxisRange& valueRange() const { return m_valueRange; }

  /// Replaces the curves with the sweep's values of the selected quantities (the others are
  /// emptied and hidden), x on `x`'s axis, and resets both axes (x to `x`'s range and title).
  /// The ratio charts read `ratios`, the sweep's (none drawn while it is null).
  /// A value axis the data have left is fitted again with room while they keep changing
  /// (refittedRange). Returns whether what lays the chart out changed (the room the axes'
  /// labels and titles take, the legend): then the plot areas need aligning again; on most
  /// frames of a drag they do not.
  bool setData(const kinematics::SweepResult& sweep, const QuantitySelection& selection, AngleUnit unit,
               const PlotXAxis& x, const QString& lengthUnit = QStringLiteral("mm"),
               const kinematics::AdvantageSeries* ratios = nullptr, DataFlow flow = DataFlow::Settled);
  /// Another tool's rows over the curves of this chart's kind (the others are ignored), each
  /// shown while its quantity is selected; the value axis covers them too. Takes effect at
  /// the next setData. Nothing changes when `overlay` is what is shown already.
  void setOverlay(const std::vector<OverlayCurve>& overlay);
  /// The markers of `quantity`'s compared column, or null.
  QScatterSeries* overlaySeries(PlotQuantity quantity) const;
  /// While the data change, setData keeps the value axis where it still serves (keepsRange);
  /// this sets it to the data's own range once they have settled. Returns whether that
  /// changed the room its labels take (then the plot areas need aligning again).
  bool settleValueRange();
  /// Moves the cursor to `x` (plot units), or hides it. Touches no data series.
  void setCursorX(std::optional<double> x);
  std::optional<double> cursorX() const { return m_cursor->x(); }
  /// The line of `quantity`, or null for a quantity of another kind.
  CurveItem* curveItem(PlotQuantity quantity) const;
  /// The samples `quantity`'s line stands for, in sweep order, gaps left out (the line draws
  /// only the vertices the screen needs of them); empty while it is not selected.
  QList<QPointF> samples(PlotQuantity quantity) const;

signals:
  /// The mouse entered (`inside`) or left `quantity`'s curve; `point` is the sample nearest
  /// the mouse, in plot units.
  void curveHovered(linkwright::ui::PlotQuantity quantity, QPointF point, bool inside);
  /// The mouse entered (`inside`) or left an overlay marker; `text` says which row it is.
  void overlayHovered(const QString& text, bool inside);
  /// The view was resized (and its chart with it).
  void resized();

protected:
  void resizeEvent(QResizeEvent* event) override;

private:
  struct Curve {
    PlotCurve curve;
    SegmentedLine line;
  };
  struct Markers {
    OverlayCurve overlay;
    QScatterSeries* series;  // owned by the chart
  };

  void removeMarkers();
  void onCurveHovered(PlotQuantity quantity, qsizetype run, QPointF point, bool inside);
  // The value axis over the data's span, with no more ticks than the plot's height can label.
  void applyValueRange();
  int tickBudget() const;
  void fitLegendNames();

  QuantityKind m_kind;
  QValueAxis* m_xAxis;
  AxisRange m_xRange;  // the last data's x range: its ticks are fitted again to a new width
  QValueAxis* m_yAxis;
  std::vector<Curve> m_curves;
  std::vector<Markers> m_markers;
  std::unique_ptr<VerticalMarker> m_cursor;
  AxisRange m_valueRange;
  double m_lo = 0.0, m_hi = 0.0;     // the data's span that m_valueRange covers
  int m_tickBudget = 0;              // the budget m_valueRange was made with
  ChartLayoutInputs m_layoutInputs;  // as of the last setData
  std::vector<SeriesRuns> m_runs;    // each curve's points of one update, reused
  std::vector<double> m_values;      // y values of one update, reused
};

}  // namespace linkwright::ui
