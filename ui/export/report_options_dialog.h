#pragma once
// Report ▸ PDF…: asks where the linkage is drawn (the input, pre-filled with where it is now),
// the table's step (default 30°, as the thesis; more than 0 and at most a turn, or the input's
// range for a linear driver), the units of the angles, ω and α and the paper. The report itself is the core's
// (kinematics/report/), the one `linkwright-cli report` writes.

#include "kinematics/report/report_pdf.h"

#include <QDialog>

class QComboBox;
class QDoubleSpinBox;

namespace linkwright::ui {

class ReportOptionsDialog : public QDialog {
  Q_OBJECT
public:
  /// `at` and `maxStep` in the input's display unit `unit` ("°" or the length unit), or in
  /// seconds ("s") on a time base.
  ReportOptionsDialog(double at, double maxStep, const QString& unit, QWidget* parent = nullptr);

  double at() const;    ///< the drawn input, display unit
  double step() const;  ///< the table's step, display unit
  kinematics::report::Paper paper() const;
  kinematics::report::ReportUnits units() const;
  void setUnits(const kinematics::report::ReportUnits& units);

  QDoubleSpinBox* atBox() const { return m_at; }
  QDoubleSpinBox* stepBox() const { return m_step; }
  QComboBox* paperBox() const { return m_paper; }
  QComboBox* unitsBox() const { return m_units; }

private:
  QDoubleSpinBox* m_at;
  QDoubleSpinBox* m_step;
  QComboBox* m_paper;
  QComboBox* m_units;
};

}  // namespace linkwright::ui
