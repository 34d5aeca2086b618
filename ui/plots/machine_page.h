#pragma once
// The Forces tab's Flywheel and motor page: what one crank turn asks of the machine, the core's
// machine request (kinematics/dynamics/machine_request.h, the figures `linkwright-cli machine`
// and Python's Linkage.machine give, to the bit) for the coefficient of speed fluctuation,
// gearbox and motor rating typed here, whose ranges and tooltips are the request's fields; and
// the check of the flywheel, the crank's speed over a turn run in time with it (forward
// dynamics), drawn between the limits Cs sets. The request runs on the worker pool, only while
// the page is on screen and once the design has settled; an edit drops the answer under way. A
// design it cannot compute for (not crank-driven, no masses) gets the core's sentence.

#include "ui/document/background_request.h"
#include "ui/document/machine_job.h"
#include "ui/plots/angle_unit.h"

#include "kinematics/dynamics/machine_request.h"

#include <QTimer>
#include <QWidget>

#include <optional>

class QDoubleSpinBox;
class QLabel;

namespace linkwright::ui {

class ForceChartView;
class MechanismDocument;

class MachinePage : public QWidget {
  Q_OBJECT
public:
  /// Reads `document`, which must outlive the page.
  explicit MachinePage(MechanismDocument* document, QWidget* parent = nullptr);

  /// Unit of the crank-angle axis. Degrees by default.
  void setAngleUnit(AngleUnit unit);
  /// Whether the page is on screen: off screen it computes nothing and catches up when shown.
  void setOnScreen(bool onScreen);
  /// Recomputes soon (once changes stop for a moment): the design or its forces changed.
  void designChanged();
  /// Recomputes now, if on screen (tests, and the timer's end): starts the request on the pool.
  void refresh();
  /// Blocks until the request under way has landed and is shown (tests).
  void waitForFigures();

  QDoubleSpinBox* speedFluctuationField() const { return m_cs; }
  QDoubleSpinBox* gearRatioField() const { return m_gearRatio; }
  QDoubleSpinBox* efficiencyField() const { return m_efficiency; }
  QDoubleSpinBox* ratedTorqueField() const { return m_ratedTorque; }
  QDoubleSpinBox* ratedSpeedField() const { return m_ratedSpeed; }
  /// The figures of the last turn computed, one a line, or why there are none.
  QString figuresText() const;
  ForceChartView* speedChart() const { return m_speed; }

private:
  using Outcome = MachineOutcome;
  void display(const Outcome& outcome);
  void refuse(const QString& why);

  MechanismDocument* m_document;
  AngleUnit m_unit = AngleUnit::Degrees;
  QDoubleSpinBox* m_cs;
  QDoubleSpinBox* m_gearRatio;
  QDoubleSpinBox* m_efficiency;
  QDoubleSpinBox* m_ratedTorque;
  QDoubleSpinBox* m_ratedSpeed;
  QLabel* m_figures;
  QString m_plain;  // the figures as plain lines, or why there are none
  ForceChartView* m_speed;
  kinematics::MachineRequest m_request;  // what the run under way, or the one shown, was asked
  BackgroundRequest<Outcome> m_run;
  QTimer m_settle;
  bool m_onScreen = false;
  bool m_stale = true;
};

}  // namespace linkwright::ui
