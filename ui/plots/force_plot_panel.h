#pragma once
// The force plots: the driving torque and the joint reaction magnitudes against time or crank
// angle (the document's plotAxis()); the shaking force on the frame (x, y, magnitude) and its
// moment, with their peaks; the polar diagram of the pin joint, or the shaking force, the
// combo box picks; and a turn's flywheel and motor figures (machine_page.h). Everything comes from a ForceResults (the core's inverse dynamics on the document's
// cycle); a crank move moves the cursors and the polar dot only. When there are no forces (no masses or loads, an unknown
// length unit) the charts hide and a line says why.

#include "ui/plots/angle_unit.h"
#include "ui/plots/force_series.h"
#include "ui/plots/plot_x_axis.h"

#include "kinematics/design/design.h"
#include "kinematics/dynamics/force_sweep.h"

#include <QTimer>
#include <QWidget>

#include <optional>
#include <vector>

class QComboBox;
class QLabel;
class QTabWidget;

namespace linkwright::ui {

class ForceChartView;
class ForceResults;
class MachinePage;
class MechanismDocument;
class PolarLoadView;

class ForcePlotPanel : public QWidget {
  Q_OBJECT
public:
  /// Reads `forces` (solved from `document`); both must outlive the panel. It does not enable
  /// `forces`: whoever shows the panel does.
  ForcePlotPanel(MechanismDocument* document, ForceResults* forces, QWidget* parent = nullptr);

  /// Draws, dashed beside the curves, those of the same linkage with the dynamics `before` (the
  /// driving torque, each joint's force, the shaking force and moment, "before balancing"), for
  /// as long as the document's design is `after`: any other edit or an undo drops them.
  void setBefore(const kinematics::Design& after, const kinematics::LinkageDynamics& before);
  /// Whether the curves from before are drawn.
  bool showsBefore() const { return m_before.has_value() && m_before->forces.has_value(); }

  /// Unit of the crank-angle axis (when the plots show the input). Degrees by default.
  void setAngleUnit(AngleUnit unit);
  /// Text and lines of the charts and the polar view at `factor` times their normal size.
  void setPresentationScale(double factor);
  /// Draws the charts and their curves in the current theme's colours (ui/colors.h).
  void refreshColors();
  /// Whether the panel is on screen (its tab chosen): off screen it re-plots nothing (the
  /// canvas's force arrows may keep the forces solved) and catches up when shown. On by default.
  void setOnScreen(bool onScreen);

  ForceChartView* torqueChart() const { return m_torque; }
  ForceChartView* jointChart() const { return m_joints; }
  ForceChartView* shakingChart() const { return m_shaking; }
  ForceChartView* shakingMomentChart() const { return m_shakingMoment; }
  /// The line under the shaking charts with the peaks and where they are.
  QString shakingPeakText() const;
  /// The pages: curves, shaking, polar diagrams, flywheel and motor.
  QTabWidget* pages() const { return m_pages; }
  MachinePage* machinePage() const { return m_machine; }
  PolarLoadView* polarView() const { return m_polar; }
  QComboBox* jointSelector() const { return m_selector; }
  /// The line that says why there are no forces, or where they are missing.
  QString statusText() const;
  /// The joints on the magnitude chart, in legend order.
  const std::vector<ForceJoint>& joints() const { return m_jointList; }

private:
  void refreshAll();
  void refreshCursor();
  void refreshPolar();
  void refreshShaking(const PlotXAxis& x, DataFlow flow, bool& relayout);
  bool shakingSelected() const;
  void alignCharts();
  void settleValueRanges();
  void showMachinePage();
  std::optional<double> cursorX() const;

  MechanismDocument* m_document;
  ForceResults* m_forces;
  AngleUnit m_unit = AngleUnit::Degrees;
  QLabel* m_status;
  ForceChartView* m_torque;
  ForceChartView* m_joints;
  ForceChartView* m_shaking;
  ForceChartView* m_shakingMoment;
  QLabel* m_shakingPeaks;
  QTabWidget* m_pages;
  QComboBox* m_selector;
  PolarLoadView* m_polar;
  MachinePage* m_machine;
  QWidget* m_charts;
  QTimer m_settleTimer;
  bool m_onScreen = true;
  bool m_stale =
      false;  // a change came while off screen: refreshAll when back  // the value axes fit the data once they stay put (PlotPanel's too)
  // The design a balance made, the dynamics it had before, and their forces on its cycle.
  struct Before {
    kinematics::Design after;
    kinematics::LinkageDynamics dynamics;
    std::optional<kinematics::ForceSweep> forces;
  };
  const kinematics::ForceSweep* beforeForces();
  std::optional<Before> m_before;
  std::vector<ForceJoint> m_jointList;
  std::vector<SeriesRuns> m_runs;  // reused between updates
  PlotXAxis m_x;                   // of the last refreshAll
  bool m_legendsRefit = true;      // the charts' legend heights fitted afresh (alignCharts)
};

}  // namespace linkwright::ui
