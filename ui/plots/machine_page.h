#pragma once
// The Forces tab's Flywheel and motor page: what one crank turn asks of the machine
// (kinematics/dynamics/machine_duty.h, the figures `linkwright-cli machine` prints), for the
// coefficient of speed fluctuation, gearbox and motor rating typed here; and the check of the
// flywheel, the crank's speed over a turn run in time with it (forward dynamics), drawn between
// the limits Cs sets. The page computes only while it is on screen, once the design has settled;
// a design it cannot compute for (not crank-driven, no masses) gets the core's sentence.

#include "ui/plots/angle_unit.h"

#include <QTimer>
#include <QWidget>

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
  /// Recomputes now, if on screen (tests, and the timer's end).
  void refresh();

  QDoubleSpinBox* speedFluctuationField() const { return m_cs; }
  QDoubleSpinBox* gearRatioField() const { return m_gearRatio; }
  QDoubleSpinBox* efficiencyField() const { return m_efficiency; }
  QDoubleSpinBox* ratedTorqueField() const { return m_ratedTorque; }
  QDoubleSpinBox* ratedSpeedField() const { return m_ratedSpeed; }
  /// The figures of the last turn computed, or why there are none.
  QString figuresText() const;
  ForceChartView* speedChart() const { return m_speed; }

private:
  MechanismDocument* m_document;
  AngleUnit m_unit = AngleUnit::Degrees;
  QDoubleSpinBox* m_cs;
  QDoubleSpinBox* m_gearRatio;
  QDoubleSpinBox* m_efficiency;
  QDoubleSpinBox* m_ratedTorque;
  QDoubleSpinBox* m_ratedSpeed;
  QLabel* m_figures;
  ForceChartView* m_speed;
  QTimer m_settle;
  bool m_onScreen = false;
  bool m_stale = true;
};

}  // namespace linkwright::ui
