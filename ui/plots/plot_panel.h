#pragma once
// The live plots against time or crank angle (the document's plotAxis(), plot_x_axis.h), one
// chart per kind, stacked so they read together: link
// and transmission angles, link ω, link α, and for linkages with sliders their positions,
// velocities and accelerations, and for a four-bar or slider-crank its velocity ratio and
// mechanical advantage (asked for by ticking them). The quantities come from the mechanism (plot_quantity.h); a
// row of checkboxes picks them, and the document is asked to compute only what is shown. Charts
// with nothing to show are hidden. Curves are re-read from the document's sweep when the
// design or request changes; a crank move only moves the cursor on each chart. Hovering a
// curve reads its value out; a four-bar's rocker limit positions are marked on the angle chart
// and the ratio charts
// (on a time base at each instant the crank passes them, or not at all, with a note saying why).
// A comparison with another tool's table (File ▸ Compare…) draws its rows over the curves until
// it is cleared or another document comes.
// The plots also decide the displayed sweep's resolution: its samples follow the plot area's
// width (times the quality the bar above the charts sets), reported once a resize settles.

#include "ui/plots/angle_unit.h"
#include "ui/plots/compare_overlay.h"
#include "ui/plots/plot_quantity.h"
#include "ui/plots/plot_x_axis.h"

#include "ui/document/mechanism_document.h"

#include <QList>
#include <QTimer>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class QChartView;
class QLabel;

class QGraphicsView;

namespace linkwright::kinematics {
struct AdvantageSeries;
}

namespace linkwright::ui {

class HoverReadout;
class LimitMarkers;
class QuantityChartView;
class QuantitySelector;
class QualityBar;

class PlotPanel : public QWidget {
  Q_OBJECT
public:
  explicit PlotPanel(MechanismDocument* document, QWidget* parent = nullptr);
  ~PlotPanel() override;

  /// Unit of every angular quantity shown (x axis included). Degrees by default.
  void setAngleUnit(AngleUnit unit);
  AngleUnit angleUnit() const { return m_unit; }
  /// Text and lines of every chart at `factor` times their normal size; above 1 (presentation
  /// mode) the quality bar and the quantity selector are hidden and only the bottom chart
  /// names the shared x axis, so the charts get the room.
  void setPresentationScale(double factor);
  /// Draws the charts and their curves in the current theme's colours (ui/colors.h).
  void refreshColors();

  /// The charts in display order (angles, ω, α, position, velocity, acceleration, velocity
  /// ratio, advantage), for image
  /// export. A chart with nothing selected or nothing to show isHidden().
  QList<QChartView*> chartViews() const;
  /// The same views as plain QGraphicsViews, so code outside ui/plots can export them
  /// without depending on Qt Charts.
  QList<QGraphicsView*> graphicsViews() const;
  /// The title of chartViews()[index] ("Link angles", ...); empty for an index out of range.
  QString chartTitle(int index) const;

  /// The mechanism's plottable quantities, and the one of `quantity` (null if it has none).
  const std::vector<PlotCurve>& curves() const { return m_curves; }
  const PlotCurve* curve(PlotQuantity quantity) const { return findCurve(m_curves, quantity); }
  /// The quantities shown; setting it ticks the boxes (and emits selectionChanged if it differs).
  QuantitySelection selection() const;
  void setSelection(const QuantitySelection& selection);

  /// The chart for one kind of quantity.
  QuantityChartView* chartView(QuantityKind kind) const;
  LimitMarkers* limitMarkers() const { return m_limits.get(); }
  /// The limit positions on the ratio charts: labelled at zero velocity ratio, lines on the advantage.
  LimitMarkers* velocityRatioLimitMarkers() const { return m_ratioLimits.get(); }
  LimitMarkers* advantageLimitMarkers() const { return m_advantageLimits.get(); }
  /// Why limit positions the analysis has are not marked; empty when they are (or there are none).
  QString limitNote() const;
  HoverReadout* hoverReadout() const { return m_readout; }
  QuantitySelector* selector() const { return m_selector; }
  QualityBar* qualityBar() const { return m_quality; }

  /// Width in pixels of the charts' (aligned) plot area; 0 while no chart is shown.
  double plotAreaWidth() const;
  /// Tells the document plotAreaWidth() now, instead of kResizeSettleMs after the last resize
  /// (a screenshot, a test). Nothing while no chart is shown: then only positions are swept,
  /// for the canvas, at the last width.
  void reportPlotWidth();
  static constexpr int kResizeSettleMs = 150;
  /// How long the data must stay put before the value axes fit them again (they stay where
  /// they still serve while the data change: keepsRange in axis_range.h).
  static constexpr int kDataSettleMs = 300;
  /// Fits the value axes to the data now, instead of kDataSettleMs after the last change.
  void settleValueRanges();
  /// Whether the charts are on screen (the main window says so when their tab is chosen). Off
  /// screen, a document change re-plots nothing (the request the plots make still follows
  /// the design); the charts catch up when they come back on screen. On by default.
  void setOnScreen(bool onScreen);
  bool isOnScreen() const { return m_onScreen; }

  /// Draws `comparison`'s rows (of the table named `source`) over the curves of their
  /// quantities, replacing any drawn before; they stay as they are while the linkage changes.
  void setComparison(const kinematics::compare::Comparison& comparison, const QString& source);
  void clearComparison();
  bool hasComparison() const { return m_comparison.has_value(); }

signals:
  /// The user (or setSelection) changed which quantities are shown.
  void selectionChanged();

private:
  void onDocumentChanged(Changes what);
  void onSelectionChanged();
  void applySelection();
  bool refreshCurves();  // true when the curves changed (the data must be set again)
  void refreshData();
  void refreshCursor();
  /// Shows the x axis's title on every chart, or when presenting on the bottom one only.
  /// Returns the charts whose title appeared or went (they need laying out again).
  QList<QuantityChartView*> showXTitles();
  /// Marks the four-bar's limit positions on the angle and ratio charts of refreshData's x
  /// axis; adds the charts whose legend changed to `changed`. Returns why they are not marked,
  /// or nothing.
  QString placeLimitMarkers(const QuantitySelection& shown, const kinematics::AdvantageSeries* ratios,
                            QList<QuantityChartView*>& changed);
  /// Aligns the shown charts' plot areas; `changed` (default: all) are laid out afresh.
  void alignCharts(const QList<QuantityChartView*>& changed);
  /// Each shown chart at least as tall as its legend needs (legendFittingHeight).
  void fitLegends();
  void alignCharts();

  MechanismDocument* m_document;
  AngleUnit m_unit = AngleUnit::Degrees;
  QualityBar* m_quality;
  QuantitySelector* m_selector;
  QTimer m_widthTimer;
  QTimer m_settleTimer;
  bool m_onScreen = true;
  bool m_presenting = false;  // setPresentationScale above 1
  bool m_stale = false;       // a change came while off screen: refreshData when back
  std::vector<PlotCurve> m_curves;
  std::array<QuantityChartView*, kQuantityKindCount> m_views{};
  std::unique_ptr<LimitMarkers> m_limits;           // on the angle chart
  std::unique_ptr<LimitMarkers> m_ratioLimits;      // the same on the velocity-ratio chart
  std::unique_ptr<LimitMarkers> m_advantageLimits;  // and on the advantage chart
  QLabel* m_limitNote;
  HoverReadout* m_readout;
  PlotXAxis m_x;  // what the charts show on x since the last refreshData
  std::optional<kinematics::compare::Comparison> m_comparison;
  QString m_comparisonSource;
  std::vector<OverlayCurve> m_overlay;  // m_comparison on m_x in m_unit
  bool m_overlayStale = false;          // m_overlay is to be placed anew
  bool m_legendsRefit = true;           // the charts' legend heights fitted afresh (fitLegends)
};

}  // namespace linkwright::ui
